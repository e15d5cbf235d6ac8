#include "render/buffer_images.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace rise {
namespace {

Image row(const std::vector<Color>& pixels) {
  Image image(static_cast<int>(pixels.size()), 1);
  for (int x = 0; x < image.width(); ++x) image.at(x, 0) = pixels[x];
  return image;
}

void expectColorNear(const Color& actual, const Color& expected, float tolerance) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TEST(BufferImages, DepthIsGreyFromNearWhiteToFarBlack) {
  const Image raw = row({Color(2.0f), Color(4.0f), Color(kInfinity), Color(6.0f), Color(5.0f)});

  const Image depth = visualizeBuffer("depth", raw);

  ASSERT_EQ(depth.width(), 5);
  ASSERT_EQ(depth.height(), 1);
  // Linear in 1 / depth: 1/2 white, 1/6 black.
  EXPECT_EQ(depth.at(0, 0), Color(1.0f));
  expectColorNear(depth.at(1, 0), Color(0.25f), 1e-6f);
  EXPECT_EQ(depth.at(2, 0), Color(0.0f));  // nothing hit
  EXPECT_EQ(depth.at(3, 0), Color(0.0f));
  expectColorNear(depth.at(4, 0), Color(0.1f), 1e-6f);
}

// A floor reaching a million units away takes the darkest levels, not all
// but the lightest: surfaces 2 to 4 units away keep half the scale.
TEST(BufferImages, AFarFloorLeavesTheNearSurfacesTheirLevels) {
  const Image depth =
      visualizeBuffer("depth", row({Color(2.0f), Color(3.0f), Color(4.0f), Color(1e6f)}));
  EXPECT_EQ(depth.at(0, 0), Color(1.0f));
  expectColorNear(depth.at(1, 0), Color(2.0f / 3.0f), 1e-5f);
  expectColorNear(depth.at(2, 0), Color(0.5f), 1e-5f);
  EXPECT_EQ(depth.at(3, 0), Color(0.0f));
}

TEST(BufferImages, DepthOfOneDistanceIsWhite) {
  const Image depth = visualizeBuffer("depth", row({Color(3.0f), Color(kInfinity)}));

  EXPECT_EQ(depth.at(0, 0), Color(1.0f));
  EXPECT_EQ(depth.at(1, 0), Color(0.0f));
}

TEST(BufferImages, NormalIsHalfNPlusHalf) {
  const Image raw =
      row({Vec3(0.0f, 0.0f, 1.0f), Vec3(-1.0f, 0.0f, 0.0f), Vec3(0.0f), Vec3(0.6f, -0.8f, 0.0f)});

  const Image normal = visualizeBuffer("normal", raw);

  EXPECT_EQ(normal.at(0, 0), Color(0.5f, 0.5f, 1.0f));
  EXPECT_EQ(normal.at(1, 0), Color(0.0f, 0.5f, 0.5f));
  EXPECT_EQ(normal.at(2, 0), Color(0.0f));  // nothing hit
  expectColorNear(normal.at(3, 0), Color(0.8f, 0.1f, 0.5f), 1e-6f);
}

// Reference values of R. Du's Turbo polynomial, evaluated in double precision.
TEST(BufferImages, CostIsTurboOfTheShareOfTheLargestCount) {
  const Image raw = row({Color(0.0f), Color(25.0f), Color(50.0f), Color(100.0f)});

  const Image cost = visualizeBuffer("cost", raw);

  expectColorNear(cost.at(0, 0), Color(0.13572138f, 0.09140261f, 0.10667330f), 1e-6f);
  expectColorNear(cost.at(1, 0), Color(0.14831316f, 0.74046542f, 0.88072330f), 1e-4f);
  expectColorNear(cost.at(2, 0), Color(0.58852206f, 0.98186438f, 0.31316870f), 1e-4f);
  // Blue is -0.0255 before the clamp.
  expectColorNear(cost.at(3, 0), Color(0.56585921f, 0.05038886f, 0.0f), 1e-4f);
}

TEST(BufferImages, CostWithoutAnyTestIsTheColdEndOfTheMap) {
  const Image cost = visualizeBuffer("cost", row({Color(0.0f), Color(0.0f)}));

  expectColorNear(cost.at(1, 0), Color(0.13572138f, 0.09140261f, 0.10667330f), 1e-6f);
}

TEST(BufferImages, UnknownNameThrows) {
  EXPECT_THROW(visualizeBuffer("albedo", Image(1, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace rise
