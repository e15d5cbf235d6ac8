#include "ray/shadow_terminator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/shapes/vertex_attributes.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

// A point of a flat triangle cut from the unit sphere, interpolating the
// sphere's normals, at barycentric coordinates (u, v).
SurfacePoint onSphericalTriangle(const std::array<Vec3, 3>& corners, const Vec2& barycentric,
                                 float normalSign = 1.0f) {
  SurfacePoint surface(
      atBarycentric(corners[0], corners[1], corners[2], barycentric),
      normalSign * glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0])));
  surface.interpolation = normalInterpolation(
      corners, {normalSign * corners[0], normalSign * corners[1], normalSign * corners[2]},
      barycentric);
  return surface;
}

const std::array<Vec3, 3> kCorners = {glm::normalize(Vec3(1.0f, 0.2f, 0.1f)),
                                      glm::normalize(Vec3(0.2f, 1.0f, 0.0f)),
                                      glm::normalize(Vec3(0.1f, 0.3f, 1.0f))};

// On a convex patch the origin rises off the flat triangle towards the
// sphere the normals describe.
TEST(ShadowTerminator, LiftsAConvexPatchsPointTowardsTheSmoothSurface) {
  for (const Vec2 barycentric :
       {Vec2(1.0f / 3.0f), Vec2(0.6f, 0.2f), Vec2(0.1f, 0.1f), Vec2(0.45f, 0.5f)}) {
    const SurfacePoint surface = onSphericalTriangle(kCorners, barycentric);
    const Vec3 origin = shadowRayOrigin(surface, surface.normal);
    EXPECT_GT(glm::dot(origin - surface.position, surface.normal), 0.0f);
    EXPECT_LT(std::abs(glm::length(origin) - 1.0f), std::abs(glm::length(surface.position) - 1.0f));
  }
}

// At the corners, on the surface already, and where the normals are the
// flat one's, nothing moves.
TEST(ShadowTerminator, LeavesCornersAndFlatTrianglesAlone) {
  const SurfacePoint corner = onSphericalTriangle(kCorners, Vec2(1.0f, 0.0f));
  EXPECT_TRUE(nearlyEqual(shadowRayOrigin(corner, corner.normal), corner.position, 1e-6f));
  SurfacePoint flat = onSphericalTriangle(kCorners, Vec2(0.3f, 0.3f));
  flat.interpolation->normals = {flat.normal, flat.normal, flat.normal};
  EXPECT_TRUE(nearlyEqual(shadowRayOrigin(flat, flat.normal), flat.position, 1e-6f));
  const SurfacePoint sphere(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(shadowRayOrigin(sphere, sphere.normal), sphere.position);
}

// Seen from inside the sphere, its normals turned inwards, the patch is
// concave: the point lies above every corner's tangent plane and stays.
TEST(ShadowTerminator, LeavesAConcavePatchsPointAlone) {
  const SurfacePoint surface = onSphericalTriangle(kCorners, Vec2(0.3f, 0.3f), -1.0f);
  EXPECT_TRUE(nearlyEqual(shadowRayOrigin(surface, surface.normal), surface.position, 1e-6f));
}

// A ray leaving the back of a convex patch must not start on its front.
TEST(ShadowTerminator, DoesNotLiftThroughTheSurfaceFromBehind) {
  const SurfacePoint surface = onSphericalTriangle(kCorners, Vec2(0.3f, 0.3f));
  EXPECT_EQ(shadowRayOrigin(surface, -surface.normal), surface.position);
  const std::optional<Ray> ray = shadowRay(surface, -surface.normal, -surface.normal, 0.5f);
  ASSERT_TRUE(ray);
  EXPECT_TRUE(nearlyEqual(ray->origin, surface.position - kRayEpsilon * surface.normal, 1e-6f));
  EXPECT_EQ(ray->time, 0.5f);
}

// The light's side is the side of the interpolated normal: a light just
// behind the flat triangle but in front of the smooth surface lights it,
// one behind the smooth surface does not; from behind, the other way round.
TEST(ShadowTerminator, SeesTheLightOnTheSmoothSurfacesSide) {
  const SurfacePoint surface = onSphericalTriangle(kCorners, Vec2(0.8f, 0.1f));
  const Vec3 smooth = glm::normalize(0.1f * kCorners[0] + 0.8f * kCorners[1] + 0.1f * kCorners[2]);
  // Along the flat triangle, tilted a little towards the smooth normal.
  const Vec3 along = glm::normalize(glm::cross(surface.normal, glm::cross(smooth, surface.normal)));
  const Vec3 grazing = glm::normalize(along - 0.02f * surface.normal);
  ASSERT_LT(glm::dot(grazing, surface.normal), 0.0f);
  ASSERT_GT(glm::dot(grazing, smooth), 0.0f);
  EXPECT_TRUE(shadowRay(surface, surface.normal, grazing, 0.0f));
  EXPECT_FALSE(shadowRay(surface, surface.normal, -grazing, 0.0f));
  EXPECT_FALSE(shadowRay(surface, -surface.normal, grazing, 0.0f));
  const SurfacePoint sphere(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f));
  EXPECT_FALSE(shadowRay(sphere, sphere.normal, Vec3(1.0f, -0.01f, 0.0f), 0.0f));
  EXPECT_TRUE(shadowRay(sphere, sphere.normal, Vec3(1.0f, 0.01f, 0.0f), 0.0f));
}

}  // namespace
}  // namespace rise
