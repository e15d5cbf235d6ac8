#include "ray/ritter_sphere.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace rise {
namespace {

TEST(RitterSphere, OfTheSixAxisPointsIsTheUnitSphere) {
  const std::vector<Vec3> points{{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const BoundingSphere sphere = ritterBoundingSphere(points);
  EXPECT_NEAR(glm::length(sphere.centre), 0.0f, 1e-6f);
  EXPECT_NEAR(sphere.radius, 1.0f, 1e-6f);
}

// The first pass takes (-2, 0, 0)-(2, 0, 0), the widest pair, as the
// diameter; the second finds (0, 3, 0) three units from the centre, outside,
// and makes the sphere of radius (2 + 3) / 2 = 2.5 that holds the old sphere
// and the point, its centre moved 0.5 towards the point. The smallest
// sphere, the triangle's circumcircle, has radius 13/6: Ritter's is
// close to it, not equal.
TEST(RitterSphere, GrowsTowardsAPointLeftOutside) {
  const std::vector<Vec3> points{{-2, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  const BoundingSphere sphere = ritterBoundingSphere(points);
  EXPECT_NEAR(sphere.centre.x, 0.0f, 1e-6f);
  EXPECT_NEAR(sphere.centre.y, 0.5f, 1e-6f);
  EXPECT_NEAR(sphere.centre.z, 0.0f, 1e-6f);
  EXPECT_NEAR(sphere.radius, 2.5f, 1e-6f);
}

TEST(RitterSphere, OfOnePointIsThePoint) {
  const std::vector<Vec3> points{{1, 2, 3}};
  const BoundingSphere sphere = ritterBoundingSphere(points);
  EXPECT_EQ(sphere.centre, Vec3(1, 2, 3));
  EXPECT_EQ(sphere.radius, 0.0f);
}

TEST(RitterSphere, HoldsEveryPointOfRandomClouds) {
  std::mt19937 random(90);
  std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f);
  for (int cloud = 0; cloud < 50; ++cloud) {
    std::vector<Vec3> points(200);
    // Stretched along x, so that the first diameter is seldom the last.
    for (Vec3& point : points)
      point = Vec3(3.0f * coordinate(random), coordinate(random), 0.3f * coordinate(random));
    const BoundingSphere sphere = ritterBoundingSphere(points);
    for (const Vec3& point : points)
      ASSERT_LE(glm::distance(point, sphere.centre), sphere.radius * (1.0f + 1e-6f));
    // No sphere around two points is narrower than half their distance.
    float widest = 0.0f;
    for (const Vec3& a : points)
      for (const Vec3& b : points) widest = std::max(widest, glm::distance(a, b));
    EXPECT_GE(sphere.radius, 0.5f * widest);
  }
}

}  // namespace
}  // namespace rise
