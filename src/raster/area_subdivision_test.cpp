#include "raster/area_subdivision.hpp"

#include <gtest/gtest.h>

#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

TEST(AreaSubdivision, DrawsAnEmptyScreenAsOneWindow) {
  const RenderResult result =
      render("area-subdivision", sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30));
  EXPECT_EQ(result.stats.value("windows"), 1.0);
  EXPECT_EQ(result.stats.value("windows_empty"), 1.0);
  EXPECT_EQ(result.stats.value("subdivisions"), 0.0);
}

// One polygon alone in the window is scan-converted there, undivided.
TEST(AreaSubdivision, DrawsALonePolygonWithoutSubdividing) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  const RenderResult result = render("area-subdivision", scene);
  EXPECT_EQ(result.stats.value("windows"), 1.0);
  EXPECT_EQ(result.stats.value("windows_one_polygon"), 1.0);
  EXPECT_EQ(result.stats.value("classified_contained"), 1.0);
  EXPECT_EQ(pixelsSeeingOtherFaces(result, render("z-buffer", scene)), 0);
}

// A triangle holding the whole screen, in front of another: the screen is
// simple as it is.
TEST(AreaSubdivision, FillsAWindowWithASurroundingPolygonInFront) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-20.0f, -20.0f, -1.0f), Vec3(20.0f, -20.0f, -1.0f),
              Vec3(0.0f, 20.0f, -1.0f));
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  const RenderResult result = render("area-subdivision", scene);
  EXPECT_EQ(result.stats.value("windows"), 1.0);
  EXPECT_EQ(result.stats.value("windows_surrounder_in_front"), 1.0);
  EXPECT_EQ(result.stats.value("classified_surrounding"), 1.0);
}

// Behind the other, the big triangle no longer settles anything: the windows
// along the small one's edges are divided down to pixels, and every window's
// classifications, shared among its pixels, plus the depth tests at the
// pixels, add up to the cost buffer's total.
TEST(AreaSubdivision, DividesWindowsDownToPixelsAlongEdges) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-20.0f, -20.0f, 1.0f), Vec3(20.0f, -20.0f, 1.0f),
              Vec3(0.0f, 20.0f, 1.0f));
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  const RenderResult result = render("area-subdivision", scene);
  EXPECT_GT(result.stats.value("subdivisions"), 10.0);
  EXPECT_GT(result.stats.value("windows_pixel"), 10.0);
  EXPECT_EQ(pixelsSeeingOtherFaces(result, render("z-buffer", scene)), 0);
  double cost = 0.0;
  for (const Color& pixel : result.buffers.at("cost").pixels()) cost += pixel.r;
  double classified = result.stats.value("depth_tests");
  for (const char* relation : {"surrounding", "intersecting", "contained", "disjoint"})
    classified += result.stats.value(std::string("classified_") + relation);
  EXPECT_NEAR(cost, classified, 1e-3 * classified);
}

}  // namespace
}  // namespace rise
