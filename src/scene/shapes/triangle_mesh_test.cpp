#include "scene/shapes/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

// The unit square in z = 0, counter-clockwise seen from +z, split along its
// diagonal from (0, 0) to (1, 1): triangle 0 below it, triangle 1 above.
TriangleMesh unitQuad() {
  return TriangleMesh(
      {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(1.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)},
      {{0, 1, 2}, {0, 2, 3}}, 0);
}

// One triangle over the unit square's lower half, at height z.
TriangleMesh triangleAt(float z) {
  return TriangleMesh({Vec3(0.0f, 0.0f, z), Vec3(1.0f, 0.0f, z), Vec3(1.0f, 1.0f, z)}, {{0, 1, 2}},
                      0);
}

Ray downAt(float x, float y) { return Ray{{x, y, 5.0f}, {0.0f, 0.0f, -1.0f}}; }

TEST(TriangleMesh, HitsEachTriangleOfAQuadAndRecordsWhich) {
  const TriangleMesh quad = unitQuad();
  const auto lower = intersect(quad, downAt(0.75f, 0.25f));
  EXPECT_TRUE(hitsAt(lower, 5.0f, {0.75f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(lower.hit.primitive, 0);
  EXPECT_EQ(lower.hit.shape, &quad);
  const auto upper = intersect(quad, downAt(0.25f, 0.75f));
  EXPECT_TRUE(hitsAt(upper, 5.0f, {0.25f, 0.75f, 0.0f}, {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(upper.hit.primitive, 1);
}

TEST(TriangleMesh, NoRaySlipsThroughTheSharedEdge) {
  EXPECT_TRUE(hitsAt(intersect(unitQuad(), downAt(0.5f, 0.5f)), 5.0f, {0.5f, 0.5f, 0.0f},
                     {0.0f, 0.0f, 1.0f}));
}

TEST(TriangleMesh, MissesBesideIt) {
  EXPECT_TRUE(misses(intersect(unitQuad(), downAt(1.5f, 0.5f))));
}

TEST(TriangleMesh, FindsTheNearestOfOverlappingTriangles) {
  // The farther triangle comes first.
  const TriangleMesh stack({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f),
                            Vec3(0.0f, 0.0f, 1.0f), Vec3(1.0f, 0.0f, 1.0f), Vec3(0.0f, 1.0f, 1.0f)},
                           {{0, 1, 2}, {3, 4, 5}}, 0);
  const auto result = intersect(stack, downAt(0.25f, 0.25f));
  EXPECT_TRUE(hitsAt(result, 4.0f, {0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(result.hit.primitive, 1);
}

TEST(TriangleMesh, TwoOverlappingMeshesKeepTheNearestInEitherOrder) {
  const TriangleMesh low = triangleAt(0.0f);
  const TriangleMesh high = triangleAt(1.0f);
  const Ray ray = downAt(0.75f, 0.25f);
  for (const auto& [first, second] : {std::pair{&low, &high}, std::pair{&high, &low}}) {
    Hit hit;
    IntersectionCounters counters;
    first->intersect(ray, 0.0f, hit, counters);
    second->intersect(ray, 0.0f, hit, counters);
    EXPECT_EQ(hit.shape, &high);
    EXPECT_FLOAT_EQ(hit.t, 4.0f);
    EXPECT_EQ(counters.tests, 2u);
  }
}

TEST(TriangleMesh, EachTriangleTakesItsOwnWinding) {
  const TriangleMesh facingDown({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(1.0f, 1.0f, 0.0f)},
                                {{0, 2, 1}}, 0);
  EXPECT_TRUE(hitsAt(intersect(facingDown, downAt(0.75f, 0.25f)), 5.0f, {0.75f, 0.25f, 0.0f},
                     {0.0f, 0.0f, -1.0f}));
}

TEST(TriangleMesh, TMinAndTheNearerHitBoundTheSearch) {
  const TriangleMesh low = triangleAt(0.0f);
  EXPECT_TRUE(misses(intersect(low, Ray{{0.75f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}}, kRayEpsilon)));
  EXPECT_TRUE(misses(intersect(low, downAt(0.75f, 0.25f), 0.0f, 4.0f), 4.0f));
}

TEST(TriangleMesh, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(unitQuad(), Ray{{0.75f, 0.25f, 5.0f}, {0.0f, 0.0f, -10.0f}});
  EXPECT_TRUE(hitsAt(result, 0.5f, {0.75f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(TriangleMesh, CountsOneTestPerTriangle) {
  EXPECT_EQ(intersect(unitQuad(), downAt(0.75f, 0.25f)).counters.tests, 2u);
  EXPECT_EQ(intersect(unitQuad(), downAt(2.0f, 2.0f)).counters.tests, 2u);
}

// The unit quad with the normals of a dome over it, leaning out from a
// point below its centre, and texture coordinates equal to x and y.
TriangleMesh domeQuad(const Vec3& domeCentre) {
  const std::vector<Vec3> corners{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(1.0f, 1.0f, 0.0f),
                                  Vec3(0.0f, 1.0f, 0.0f)};
  MeshGeometry geometry{corners, {}, {}, {{0, 1, 2}, {0, 2, 3}}};
  for (const Vec3& corner : corners) {
    geometry.normals.push_back(glm::normalize(corner - domeCentre));
    geometry.uvs.emplace_back(corner.x, corner.y);
  }
  return TriangleMesh(std::move(geometry), 0);
}

TEST(TriangleMesh, InterpolatesVertexNormalsIntoTheShadingNormal) {
  const Vec3 below(0.5f, 0.5f, -1.0f);
  const TriangleMesh dome = domeQuad(below);
  // (0.75, 0.25) is 0.25 v0 + 0.5 v1 + 0.25 v2 of the lower triangle.
  const auto result = intersect(dome, downAt(0.75f, 0.25f));
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.75f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
  const Vec3 blend = 0.25f * glm::normalize(Vec3(0.0f) - below) +
                     0.5f * glm::normalize(Vec3(1.0f, 0.0f, 0.0f) - below) +
                     0.25f * glm::normalize(Vec3(1.0f, 1.0f, 0.0f) - below);
  EXPECT_TRUE(shape_testing::nearlyEqual(result.surface.shadingNormal, glm::normalize(blend)));
  EXPECT_EQ(result.surface.uv, Vec2(0.75f, 0.25f));
}

TEST(TriangleMesh, KeepsTheFlatNormalWhereTheVertexNormalsFaceAway) {
  // Normals leaning out from a point above the quad face -z, against its winding.
  const auto result = intersect(domeQuad({0.5f, 0.5f, 1.0f}), downAt(0.75f, 0.25f));
  EXPECT_EQ(result.surface.shadingNormal, Vec3(0.0f, 0.0f, 1.0f));
}

TEST(TriangleMesh, WithoutVertexNormalsShadesWithTheFlatNormal) {
  const auto result = intersect(unitQuad(), downAt(0.75f, 0.25f));
  EXPECT_EQ(result.surface.shadingNormal, result.surface.normal);
  EXPECT_EQ(result.surface.uv, Vec2(0.0f));
}

}  // namespace
}  // namespace rise
