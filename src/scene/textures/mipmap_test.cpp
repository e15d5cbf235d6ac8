#include "scene/textures/mipmap.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

// 64 x 32 texels: red in a band of rows 8 to 11, and columns that
// alternate dark and light blue, one texel wide.
Image bandAndColumns() {
  Image image(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x)
      image.at(x, y) = Color(y >= 8 && y < 12 ? 1.0f : 0.0f, 0.2f, x % 2 == 0 ? 0.0f : 1.0f);
  return image;
}

// Footprints in texels of level 0 (64 x 32), as steps of u and v.
PixelFootprint footprint(const Vec2& acrossX, const Vec2& downY) {
  return {acrossX / Vec2(64.0f, 32.0f), downY / Vec2(64.0f, 32.0f)};
}

TEST(MipMap, AConstantImageReadsAsItselfOverAnyFootprint) {
  const MipMap mipmap(Image(16, 8, Color(0.3f, 0.6f, 0.9f)));
  for (const PixelFootprint& step : {PixelFootprint{}, PixelFootprint{{0.01f, 0.0f}, {0.0f, 0.02f}},
                                     PixelFootprint{{0.5f, 0.1f}, {0.02f, -0.01f}},
                                     PixelFootprint{{3.0f, 0.0f}, {0.0f, 0.0f}}}) {
    EXPECT_TRUE(nearlyEqual(mipmap.trilinearAt({0.3f, 0.7f}, step), Color(0.3f, 0.6f, 0.9f)));
    EXPECT_TRUE(
        nearlyEqual(mipmap.ellipticalAverageAt({0.3f, 0.7f}, step), Color(0.3f, 0.6f, 0.9f)));
  }
}

// A footprint 16 texels long across the columns and none down the rows: the
// elliptical average blends the columns and keeps to the band, where the
// trilinear mipmap's square blurs the rows around it in too.
TEST(MipMap, TheEllipticalAverageFollowsALongFootprint) {
  const MipMap mipmap(bandAndColumns());
  const Vec2 inTheBand(20.5f / 64.0f, 1.0f - 10.0f / 32.0f);
  const PixelFootprint alongTheRows = footprint({16.0f, 0.0f}, {0.0f, 0.0f});
  const Color elliptical = mipmap.ellipticalAverageAt(inTheBand, alongTheRows);
  EXPECT_NEAR(elliptical.b, 0.5f, 0.05f);
  EXPECT_GT(elliptical.r, 0.9f);
  EXPECT_LT(mipmap.trilinearAt(inTheBand, alongTheRows).r, 0.5f);
}

// Turned 90 degrees, the footprint runs down the columns: the band blurs
// and the light column stays.
TEST(MipMap, TheEllipticalAverageTurnsWithTheFootprint) {
  const MipMap mipmap(bandAndColumns());
  const Vec2 inTheBand(21.5f / 64.0f, 1.0f - 10.0f / 32.0f);
  const Color average =
      mipmap.ellipticalAverageAt(inTheBand, footprint({0.0f, 0.0f}, {0.0f, 8.0f}));
  EXPECT_GT(average.b, 0.8f);
  EXPECT_LT(average.r, 0.7f);
}

// Longer than kMostAnisotropy times its width, a footprint is read on a
// coarser level: still the mean along it, and a colour between the texels'.
TEST(MipMap, TheEllipticalAverageStaysBoundedOnAVeryLongFootprint) {
  const MipMap mipmap(bandAndColumns());
  const Color average =
      mipmap.ellipticalAverageAt({0.5f, 0.5f}, footprint({1000.0f, 1.0f}, {0.0f, 0.001f}));
  EXPECT_NEAR(average.b, 0.5f, 0.05f);
  EXPECT_GE(average.r, 0.0f);
  EXPECT_LE(average.r, 1.0f);
}

// A footprint that spans the repeated texture a million times over, as a
// texture scaled by 1000 seen at a grazing angle: the mean of the whole
// texture, and at once (summing every period took minutes a pixel).
TEST(MipMap, AFootprintWiderThanTheTextureReadsItsMean) {
  const MipMap mipmap(bandAndColumns());
  const Color mean(4.0f / 32.0f, 0.2f, 0.5f);
  for (const PixelFootprint& wide :
       {footprint({1e6f, 0.0f}, {0.0f, 1e6f}), footprint({1e7f, 3e6f}, {-2e5f, 4e6f}),
        footprint({INFINITY, 0.0f}, {0.0f, 1.0f})})
    EXPECT_TRUE(nearlyEqual(mipmap.ellipticalAverageAt({0.3f, 0.6f}, wide), mean, 1e-3f));
}

}  // namespace
}  // namespace rise
