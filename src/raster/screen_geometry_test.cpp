#include "raster/screen_geometry.hpp"

#include <gtest/gtest.h>

#include "raster/polygon_clipping.hpp"
#include "scene/shapes/box.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using raster_testing::addTriangle;
using raster_testing::sceneSeenFrom;

struct Projected {
  TessellatedScene tessellated;
  ScreenGeometry screen;
};

Projected project(const Scene& scene, bool culling = true) {
  RenderSettings settings = settingsFor(scene);
  Projected result{tessellateForRaster(scene, settings), {}};
  const ViewProjection view(ViewFrame(scene.camera, settings.width, settings.height));
  result.screen = projectScene(result.tessellated, view, culling, Workers(2));
  return result;
}

// From (3, 4, -5) the eye sees the box's +x, +y and -z faces, two triangles
// each; the other three face away.
TEST(ScreenGeometry, CullsTheBackFacesOfASolid) {
  Scene scene = sceneSeenFrom(Vec3(3.0f, 4.0f, -5.0f), 64, 48);
  scene.shapes.push_back(std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f), 0));
  const Projected culled = project(scene);
  EXPECT_EQ(culled.screen.counters.polygonsIn, 12u);
  EXPECT_EQ(culled.screen.counters.culled, 6u);
  EXPECT_EQ(culled.screen.polygons.size(), 6u);
  for (const ScreenFace& face : culled.screen.faces) EXPECT_TRUE(face.frontFacing);

  const Projected kept = project(scene, false);
  EXPECT_EQ(kept.screen.counters.culled, 0u);
  EXPECT_EQ(kept.screen.polygons.size(), 12u);
}

// A lone triangle is seen from both sides: its back is drawn, not culled.
TEST(ScreenGeometry, KeepsTheBackOfAnOpenSurface) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 64, 48);
  // Counter-clockwise seen from +z: the eye, at -z, sees its back.
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  const Projected projected = project(scene);
  ASSERT_EQ(projected.screen.polygons.size(), 1u);
  EXPECT_FALSE(projected.screen.faces[0].frontFacing);
}

// A triangle reaching behind the eye is cut at the near plane and the sides
// of the image: every corner ends near the image, in front of the eye.
TEST(ScreenGeometry, ClipsToTheViewVolume) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 64, 48);
  addTriangle(scene, Vec3(-20.0f, -1.0f, -10.0f), Vec3(20.0f, -1.0f, -10.0f),
              Vec3(0.0f, -1.0f, 30.0f));
  addTriangle(scene, Vec3(10.0f, 10.0f, 0.0f), Vec3(12.0f, 10.0f, 0.0f), Vec3(11.0f, 12.0f, 0.0f));
  const Projected projected = project(scene);
  EXPECT_EQ(projected.screen.counters.clipped, 1u);
  EXPECT_EQ(projected.screen.counters.outside, 1u);
  ASSERT_EQ(projected.screen.polygons.size(), 1u);
  for (const Vec3& corner : projected.screen.cornersOf(projected.screen.polygons[0])) {
    EXPECT_GT(corner.z, 0.0f);
    EXPECT_GE(corner.x, -1.001f);
    EXPECT_LE(corner.x, 65.001f);
    EXPECT_GE(corner.y, -1.001f);
    EXPECT_LE(corner.y, 49.001f);
  }
}

// At a pixel centre, the face's weights give the barycentric coordinates of
// the point the primary ray meets, and its inverse depth that point's 1 / n:
// perspective-correct, not the screen-space ones.
TEST(ScreenGeometry, InterpolatesAsThePrimaryRaySees) {
  Scene scene = sceneSeenFrom(Vec3(0.5f, 1.0f, -4.0f), 80, 60);
  const Vec3 a(-2.0f, -1.0f, -1.0f), b(2.0f, -1.5f, 3.0f), c(0.0f, 2.0f, 1.0f);
  addTriangle(scene, a, b, c);
  const Projected projected = project(scene);
  ASSERT_EQ(projected.screen.faces.size(), 1u);
  const ScreenFace& face = projected.screen.faces[0];
  const ViewFrame frame(scene.camera, 80, 60);
  const ViewProjection view(frame);
  for (const Vec2 centre : {Vec2(40.5f, 30.5f), Vec2(25.5f, 40.5f), Vec2(52.5f, 22.5f)}) {
    const Ray ray = frame.primaryRay(centre.x, centre.y);
    float t;
    Vec2 uv;
    ASSERT_TRUE(intersectTriangle(ray, a, b, c, 0.0f, kInfinity, t, uv));
    const Vec3 weights = face.barycentricAt(centre);
    EXPECT_NEAR(weights.y, uv.x, 1e-4f);
    EXPECT_NEAR(weights.z, uv.y, 1e-4f);
    EXPECT_NEAR(weights.x, 1.0f - uv.x - uv.y, 1e-4f);
    const float n = view.toCamera(ray.at(t)).z;
    EXPECT_NEAR(face.inverseDepthAt(centre), 1.0f / n, 1e-5f);
    // A point nearer the eye along the ray is in front of the face's plane.
    const Vec3 nearer(centre, 1.0f / (0.5f * n));
    EXPECT_GT(signedDistance(face.plane(), nearer), 0.0f);
  }
}

}  // namespace
}  // namespace rise
