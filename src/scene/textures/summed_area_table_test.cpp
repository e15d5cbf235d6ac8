#include "scene/textures/summed_area_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

// 5 x 3 texels of colours that differ in every channel.
Image oddTexels() {
  Image image(5, 3);
  for (int texel = 0; texel < 15; ++texel) {
    const int x = texel % 5, y = texel / 5;
    image.at(x, y) = Color(static_cast<float>(x), static_cast<float>(y),
                           static_cast<float>((7 * x + 3 * y) % 5));
  }
  return image;
}

// The mean over the rectangle by brute force: the texels repeated, each
// constant over its unit square, integrated over 1/16 texel cells.
Color meanByCells(const Image& image, const Vec2& low, const Vec2& high) {
  constexpr int kCells = 16;
  Color sum(0.0f);
  int cells = 0;
  for (float y = low.y + 0.5f / kCells; y < high.y; y += 1.0f / kCells)
    for (float x = low.x + 0.5f / kCells; x < high.x; x += 1.0f / kCells) {
      const auto column = static_cast<int>(std::floor(x)), row = static_cast<int>(std::floor(y));
      sum += image.at(((column % 5) + 5) % 5, ((row % 3) + 3) % 3);
      ++cells;
    }
  return sum / static_cast<float>(cells);
}

TEST(SummedAreaTable, GivesAWholeTexelAndTheWholeImage) {
  const Image image = oddTexels();
  const SummedAreaTable table(image);
  EXPECT_TRUE(nearlyEqual(table.meanOver({2, 1}, {3, 2}), image.at(2, 1)));
  EXPECT_TRUE(nearlyEqual(table.meanOver({0, 0}, {5, 3}), meanByCells(image, {0, 0}, {5, 3})));
}

// Rectangles with fractional corners, across the image's edges and larger
// than the image: the texture repeats.
TEST(SummedAreaTable, AveragesAnyRectangleOfTheRepeatedImage) {
  const Image image = oddTexels();
  const SummedAreaTable table(image);
  for (const auto& [low, high] : {std::pair{Vec2(0.25f, 0.5f), Vec2(3.75f, 2.25f)},
                                  std::pair{Vec2(4.5f, 2.5f), Vec2(5.5f, 3.5f)},
                                  std::pair{Vec2(-1.25f, -0.75f), Vec2(1.5f, 0.5f)},
                                  std::pair{Vec2(-3.0f, 1.25f), Vec2(9.5f, 1.75f)},
                                  std::pair{Vec2(-12.5f, -7.25f), Vec2(-2.0f, 4.0f)}})
    EXPECT_TRUE(nearlyEqual(table.meanOver(low, high), meanByCells(image, low, high), 1e-3f))
        << shape_testing::text(Vec3(low, 0.0f)) << " to " << shape_testing::text(Vec3(high, 0.0f));
}

// A one-texel box slid between two texel centres blends them linearly, as a
// bilinear look-up does.
TEST(SummedAreaTable, AOneTexelBoxIsBilinear) {
  const Image image = oddTexels();
  const SummedAreaTable table(image);
  const Color mean = table.meanOver({1.25f, 1.0f}, {2.25f, 2.0f});
  EXPECT_TRUE(nearlyEqual(mean, glm::mix(image.at(1, 1), image.at(2, 1), 0.25f)));
}

}  // namespace
}  // namespace rise
