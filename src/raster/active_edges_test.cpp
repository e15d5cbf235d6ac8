#include "raster/active_edges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rise {
namespace {

// The crossings of the band's scanlines, one list per scanline.
std::vector<std::vector<float>> crossingsOf(const ScreenGeometry& screen, const PixelRect& band) {
  const std::vector<int> polygons{0};
  EdgeListCounters counters;
  ActiveEdgeList edges(screen, band, polygons, counters);
  std::vector<std::vector<float>> crossings;
  for (int y = band.y0; y < band.y1; ++y) {
    edges.advanceTo(y);
    std::vector<float>& row = crossings.emplace_back();
    for (const ActiveEdge& edge : edges.active()) row.push_back(edge.x);
  }
  return crossings;
}

TEST(ActiveEdgeList, CrossesEachScanlineCentreWhereTheEdgesDo) {
  ScreenGeometry screen;
  screen.addPolygon(
      0, std::vector{Vec3(0.0f, 0.0f, 1.0f), Vec3(8.0f, 0.0f, 1.0f), Vec3(0.0f, 8.0f, 1.0f)});
  const std::vector<std::vector<float>> crossings = crossingsOf(screen, {0, 0, 8, 4});
  ASSERT_EQ(crossings.size(), 4u);
  for (int y = 0; y < 4; ++y) {
    ASSERT_EQ(crossings[y].size(), 2u) << "scanline " << y;
    EXPECT_FLOAT_EQ(crossings[y][0] + crossings[y][1], 8.0f - (y + 0.5f)) << "scanline " << y;
  }
}

// A shadow volume's far side projects towards infinity, and a corner in the
// eye's plane to no place at all: the edges they end still cross whole
// scanlines, or none.
TEST(ActiveEdgeList, TakesCornersAtInfinityAndWithNoPlace) {
  ScreenGeometry screen;
  const float inf = kInfinity;
  screen.addPolygon(0, std::vector{Vec3(2.0f, 1.0f, 1.0f), Vec3(inf, inf, 1.0f),
                                   Vec3(std::nanf(""), 3.0f, 1.0f), Vec3(1.0f, -inf, 1.0f)});
  const std::vector<std::vector<float>> crossings = crossingsOf(screen, {0, 0, 8, 8});
  EXPECT_EQ(crossings.size(), 8u);
  for (float end : {inf, -inf, std::nanf(""), 1e30f, -1e30f}) {
    const auto [first, past] = centresOfSpan(1.0f, end, 16);
    EXPECT_LE(0, first);
    EXPECT_LE(past, 16);
  }
}

}  // namespace
}  // namespace rise
