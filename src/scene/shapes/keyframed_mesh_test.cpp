#include "scene/shapes/keyframed_mesh.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;
using shape_testing::nearlyEqual;

// One triangle over the unit square's lower half that rises from z = 0 at
// time 0 to z = 2 at time 1, its vertex normals turning from +z to +x
// (normals that need not match the flat one: they are what shading uses).
MeshGeometry pose(float z, const Vec3& normal) {
  return MeshGeometry{{Vec3(0.0f, 0.0f, z), Vec3(1.0f, 0.0f, z), Vec3(1.0f, 1.0f, z)},
                      {normal, normal, normal},
                      {Vec2(0.0f), Vec2(1.0f, 0.0f), Vec2(1.0f, 1.0f)},
                      {{0, 1, 2}}};
}

KeyframedMesh risingTriangle() {
  return KeyframedMesh(pose(0.0f, {0.0f, 0.0f, 1.0f}), pose(2.0f, glm::normalize(Vec3(1, 0, 1))),
                       0);
}

Ray downAt(float x, float y, float time) { return Ray{{x, y, 5.0f}, {0.0f, 0.0f, -1.0f}, time}; }

TEST(KeyframedMesh, PassesThroughEveryKeyframeInTurn) {
  // Up to z = 2 at time 0.5, down to z = 1 at time 1.
  const KeyframedMesh mesh({pose(0.0f, {0.0f, 0.0f, 1.0f}), pose(2.0f, {0.0f, 0.0f, 1.0f}),
                            pose(1.0f, {0.0f, 0.0f, 1.0f})},
                           0);
  for (const auto& [time, z] : {std::pair{0.25f, 1.0f}, {0.5f, 2.0f}, {0.75f, 1.5f}, {1.0f, 1.0f}})
    EXPECT_TRUE(hitsAt(intersect(mesh, downAt(0.75f, 0.25f, time)), 5.0f - z, {0.75f, 0.25f, z},
                       {0.0f, 0.0f, 1.0f}))
        << time;
  EXPECT_FLOAT_EQ(mesh.bounds().max.z, 2.0f);
}

TEST(KeyframedMesh, MeetsEachRayWhereTheMeshIsAtTheRaysTime) {
  const KeyframedMesh mesh = risingTriangle();
  EXPECT_TRUE(hitsAt(intersect(mesh, downAt(0.75f, 0.25f, 0.0f)), 5.0f, {0.75f, 0.25f, 0.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(hitsAt(intersect(mesh, downAt(0.75f, 0.25f, 0.5f)), 4.0f, {0.75f, 0.25f, 1.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(hitsAt(intersect(mesh, downAt(0.75f, 0.25f, 1.0f)), 3.0f, {0.75f, 0.25f, 2.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(misses(intersect(mesh, downAt(0.25f, 0.75f, 0.5f))));
}

TEST(KeyframedMesh, InterpolatesTheNormalsInTimeAndTheTextureAcrossTheTriangle) {
  const KeyframedMesh mesh = risingTriangle();
  const auto start = intersect(mesh, downAt(0.75f, 0.25f, 0.0f));
  EXPECT_TRUE(nearlyEqual(start.surface.shadingNormal, {0.0f, 0.0f, 1.0f}));
  // Halfway, the blend of +z and (+x +z)/sqrt(2), made unit.
  const auto halfway = intersect(mesh, downAt(0.75f, 0.25f, 0.5f));
  const Vec3 blend = glm::normalize(Vec3(0.0f, 0.0f, 1.0f) + glm::normalize(Vec3(1, 0, 1)));
  EXPECT_TRUE(nearlyEqual(halfway.surface.shadingNormal, blend));
  EXPECT_TRUE(nearlyEqual(Vec3(halfway.surface.uv, 0.0f), {0.75f, 0.25f, 0.0f}));
}

TEST(KeyframedMesh, ATrianglesBoxHoldsItThroughoutTheShutterInterval) {
  // Corners that move apart as well as up: the box is that of both poses.
  const MeshGeometry start{
      {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)}, {}, {}, {{0, 1, 2}}};
  const MeshGeometry end{{Vec3(-1.0f, 0.0f, 2.0f), Vec3(3.0f, 0.0f, 1.0f), Vec3(0.0f, 2.0f, 3.0f)},
                         {},
                         {},
                         {{0, 1, 2}}};
  const KeyframedMesh mesh(start, end, 0);
  ASSERT_EQ(mesh.primitiveCount(), 1);
  const Bounds3 box = mesh.primitiveBounds(0);
  EXPECT_EQ(box.min, Vec3(-1.0f, 0.0f, 0.0f));
  EXPECT_EQ(box.max, Vec3(3.0f, 2.0f, 3.0f));
  EXPECT_EQ(mesh.bounds().min, box.min);
  EXPECT_EQ(mesh.bounds().max, box.max);
  for (const float time : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
    for (int vertex = 0; vertex < 3; ++vertex) {
      const Vec3 corner = glm::mix(start.positions[vertex], end.positions[vertex], time);
      EXPECT_TRUE(glm::all(glm::lessThanEqual(box.min, corner)) &&
                  glm::all(glm::lessThanEqual(corner, box.max)))
          << "time " << time << ", corner " << vertex;
    }
  }
}

TEST(KeyframedMesh, TestsOneTriangleAsAPrimitive) {
  const KeyframedMesh mesh = risingTriangle();
  Hit hit;
  IntersectionCounters counters;
  ASSERT_TRUE(mesh.intersectPrimitive(0, downAt(0.75f, 0.25f, 0.5f), 0.0f, hit, counters));
  EXPECT_FLOAT_EQ(hit.t, 4.0f);
  EXPECT_EQ(hit.shape, &mesh);
  EXPECT_EQ(hit.primitive, 0);
  EXPECT_EQ(counters.tests, 1u);
}

TEST(KeyframedMesh, TessellatesThePoseAtTheGivenTime) {
  TessellationSettings settings;
  settings.time = 0.5f;
  Tessellation tessellation;
  risingTriangle().tessellate(settings, tessellation);
  ASSERT_EQ(tessellation.triangles.size(), 1u);
  ASSERT_EQ(tessellation.vertices.size(), 3u);
  const auto& [a, b, c] = tessellation.triangles[0];
  EXPECT_TRUE(nearlyEqual(tessellation.vertices[a].position, {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearlyEqual(tessellation.vertices[b].position, {1.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearlyEqual(tessellation.vertices[c].position, {1.0f, 1.0f, 1.0f}));
  const Vec3 blend = glm::normalize(Vec3(0.0f, 0.0f, 1.0f) + glm::normalize(Vec3(1, 0, 1)));
  EXPECT_TRUE(nearlyEqual(tessellation.vertices[b].normal, blend));
}

}  // namespace
}  // namespace rise
