#include "raster/depth_sort.hpp"

#include <gtest/gtest.h>

#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

// Two triangles, one wholly behind the other: sorted by their farthest
// points, the farther comes first, and the search for polygons it may hide
// stops at once at the nearer one, wholly nearer than it.
TEST(DepthSort, PaintsBackToFront) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-1.0f, -1.0f, -1.0f), Vec3(1.0f, -1.0f, -1.0f), Vec3(0.0f, 1.0f, -1.0f));
  addTriangle(scene, Vec3(-2.0f, 1.0f, 1.0f), Vec3(2.0f, 1.0f, 1.0f), Vec3(0.0f, -2.0f, 1.0f));
  const RenderResult result = render("depth-sort", scene);
  EXPECT_EQ(result.stats.value("comparisons"), 0.0);
  EXPECT_EQ(result.stats.value("moves"), 0.0);
  // The overlap is painted twice, the near triangle last.
  EXPECT_GT(result.stats.value("overdraw"), 1.0);
  EXPECT_EQ(result.buffers.at("cost").at(20, 15).r, 2.0f);
  EXPECT_EQ(pixelsDisagreeingWithRays(scene, settingsFor(scene), result), 0);
}

// A triangle leaning back, from z = -2 at its foot to z = 6 at its top, and a
// small one behind its lower part: sorted by their farthest points the
// leaning one comes first, yet it hides the small one, which lies wholly
// behind its plane, so the small one moves ahead of it.
TEST(DepthSort, MovesAPolygonThatMustBePaintedFirst) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-1.0f, -1.0f, -2.0f), Vec3(1.0f, -1.0f, -2.0f), Vec3(0.0f, 3.0f, 6.0f));
  addTriangle(scene, Vec3(-0.5f, -0.9f, 0.0f), Vec3(0.5f, -0.9f, 0.0f), Vec3(0.0f, -0.1f, 0.0f));
  const RenderResult result = render("depth-sort", scene);
  EXPECT_EQ(result.stats.value("comparisons"), 2.0);  // P with Q, then Q with P
  EXPECT_EQ(result.stats.value("moves"), 1.0);
  EXPECT_EQ(result.stats.value("splits"), 0.0);
  EXPECT_EQ(pixelsDisagreeingWithRays(scene, settingsFor(scene), result), 0);
}

// Two triangles piercing each other cannot be ordered: one is split along
// the other's plane, and the pieces are painted in their places.
TEST(DepthSort, SplitsInterpenetratingPolygons) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  addTriangle(scene, Vec3(-1.5f, -1.0f, 0.0f), Vec3(1.5f, -1.0f, 0.0f), Vec3(0.0f, 1.2f, 0.0f));
  addTriangle(scene, Vec3(-1.5f, 0.0f, -1.0f), Vec3(1.5f, 0.0f, 1.0f), Vec3(0.0f, -1.2f, 0.0f));
  const RenderResult result = render("depth-sort", scene);
  EXPECT_EQ(result.stats.value("splits"), 1.0);
  EXPECT_EQ(result.stats.value("polygons_painted"), 3.0);
  EXPECT_EQ(result.stats.value("unresolved_overlaps"), 0.0);
  EXPECT_LE(pixelsDisagreeingWithRays(scene, settingsFor(scene), result), 1);
}

}  // namespace
}  // namespace rise
