#include "raster/polygon_coverage.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace rise {
namespace {

// How many of the polygons cover each pixel of a width x height image.
std::vector<int> coverCounts(const std::vector<std::vector<Vec3>>& polygons, int width,
                             int height) {
  std::vector<int> counts(static_cast<std::size_t>(width) * height, 0);
  for (const auto& polygon : polygons)
    PolygonCoverage(polygon).forEachPixel({0, 0, width, height},
                                          [&](int x, int y) { ++counts[y * width + x]; });
  return counts;
}

// A square cut into triangles whose corners sit exactly on pixel centres, so
// that every edge passes through centres: the fill rule alone decides them.
TEST(PolygonCoverage, DrawsEveryPixelOfAFanOnce) {
  const Vec3 centre(4.5f, 4.5f, 1.0f);
  const std::array<Vec3, 8> rim = {Vec3(0.5f, 0.5f, 1.0f), Vec3(4.5f, 0.5f, 1.0f),
                                   Vec3(8.5f, 0.5f, 1.0f), Vec3(8.5f, 4.5f, 1.0f),
                                   Vec3(8.5f, 8.5f, 1.0f), Vec3(4.5f, 8.5f, 1.0f),
                                   Vec3(0.5f, 8.5f, 1.0f), Vec3(0.5f, 4.5f, 1.0f)};
  std::vector<std::vector<Vec3>> fan;
  for (std::size_t i = 0; i < rim.size(); ++i) fan.push_back({centre, rim[i], rim[(i + 1) % 8]});
  const std::vector<int> counts = coverCounts(fan, 10, 10);
  // The square's centres run from 0.5 to 8.5; its right and bottom edges are
  // not its own, so pixels 0 to 7 are drawn, each once.
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      EXPECT_EQ(counts[y * 10 + x], (x < 8 && y < 8) ? 1 : 0) << x << ", " << y;
}

// The same edge run in either direction by two polygons, at an angle that
// rounding makes inexact.
TEST(PolygonCoverage, GivesAnEdgesPixelsToOneSideOnly) {
  const Vec3 a(0.3f, 0.1f, 1.0f), b(17.7f, 13.9f, 1.0f);
  const Vec3 left(0.2f, 14.0f, 1.0f), right(18.0f, 0.0f, 1.0f);
  const std::vector<int> counts = coverCounts({{a, b, left}, {b, a, right}}, 20, 15);
  int twice = 0;
  for (int count : counts) twice += count > 1;
  EXPECT_EQ(twice, 0);
  // The quadrilateral a-right-b-left holds these centres strictly.
  EXPECT_EQ(counts[7 * 20 + 9], 1);
  EXPECT_EQ(counts[3 * 20 + 12], 1);
}

TEST(PolygonCoverage, OwnsTopAndLeftEdgesOnly) {
  // The pixel square of centres (1.5..3.5) x (1.5..3.5), corners on centres.
  const PolygonCoverage square(std::vector{Vec3(1.5f, 1.5f, 1.0f), Vec3(3.5f, 1.5f, 1.0f),
                                           Vec3(3.5f, 3.5f, 1.0f), Vec3(1.5f, 3.5f, 1.0f)});
  EXPECT_TRUE(square.covers(Vec2(1.5f, 2.5f)));   // left edge
  EXPECT_TRUE(square.covers(Vec2(2.5f, 1.5f)));   // top edge
  EXPECT_FALSE(square.covers(Vec2(3.5f, 2.5f)));  // right edge
  EXPECT_FALSE(square.covers(Vec2(2.5f, 3.5f)));  // bottom edge
  EXPECT_TRUE(square.covers(Vec2(2.5f, 2.5f)));
}

TEST(PolygonCoverage, CoversNothingWithoutArea) {
  const PolygonCoverage line(
      std::vector{Vec3(0.5f, 0.5f, 1.0f), Vec3(5.5f, 5.5f, 1.0f), Vec3(3.5f, 3.5f, 1.0f)});
  EXPECT_TRUE(line.isEmpty());
  EXPECT_FALSE(line.covers(Vec2(3.5f, 3.5f)));
}

// A shadow volume's far side projects towards infinity; its bounds must still
// be whole numbers of pixels, and a corner with no place adds none.
TEST(PolygonCoverage, BoundsCornersAtInfinityByPixelsFarOutside) {
  const float inf = kInfinity;
  const PixelRect bounds =
      pixelBoundsOf(std::vector{Vec3(2.0f, 3.0f, 1.0f), Vec3(inf, 3.0f, 1.0f),
                                Vec3(2.0f, -inf, 1.0f), Vec3(std::nanf(""), 1e30f, 1.0f)});
  EXPECT_EQ(bounds.x0, 2);
  EXPECT_EQ(bounds.y1, 3);
  EXPECT_GT(bounds.x1, 1 << 20);
  EXPECT_LT(bounds.y0, -(1 << 20));
  const PixelRect none = pixelBoundsOf(std::span<const Vec3>());
  EXPECT_TRUE(none.isEmpty());
}

TEST(PolygonCoverage, TellsWindowsHeldFromWindowsApart) {
  const PolygonCoverage triangle(
      std::vector{Vec3(0.0f, 0.0f, 1.0f), Vec3(10.0f, 0.0f, 1.0f), Vec3(0.0f, 10.0f, 1.0f)});
  EXPECT_TRUE(triangle.holds(Vec2(1.0f), Vec2(4.0f)));
  EXPECT_FALSE(triangle.holds(Vec2(4.0f), Vec2(7.0f)));  // crosses the long edge
  EXPECT_FALSE(triangle.edgeSeparates(Vec2(4.0f), Vec2(7.0f)));
  EXPECT_TRUE(triangle.edgeSeparates(Vec2(6.0f), Vec2(9.0f)));
  EXPECT_EQ(triangle.pixelBounds().x0, 0);
  EXPECT_EQ(triangle.pixelBounds().x1, 10);
}

}  // namespace
}  // namespace rise
