#include "reports/step_shapes.hpp"

#include <gtest/gtest.h>

namespace rise {
namespace {

int pixelsDrawnOn(const Image& image) {
  int drawn = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) drawn += image.at(x, y) != Color(0.0f);
  return drawn;
}

TEST(StepShapes, DrawASegmentEveryPixelAlongIt) {
  Image image(16, 8);
  drawShapes(image, {{StepShape::Kind::Segment, "edge", {Vec2(2.5f, 3.5f), Vec2(12.5f, 3.5f)}}});
  EXPECT_EQ(pixelsDrawnOn(image), 11);
  EXPECT_NE(image.at(7, 3), Color(0.0f));
}

// A polygon of the step reaching far outside the image (towards a shadow
// volume's far side) is drawn where it crosses the image, at once.
TEST(StepShapes, DrawOnlyWhatCrossesTheImageOfShapesReachingFarOutside) {
  Image image(16, 8);
  drawShapes(image, {{StepShape::Kind::Polygon,
                      "polygon",
                      {Vec2(-1e9f, 4.5f), Vec2(1e9f, 4.5f), Vec2(kInfinity, 1e30f)}}});
  EXPECT_EQ(pixelsDrawnOn(image), 16);
  EXPECT_NE(image.at(0, 4), Color(0.0f));
  EXPECT_NE(image.at(15, 4), Color(0.0f));
}

}  // namespace
}  // namespace rise
