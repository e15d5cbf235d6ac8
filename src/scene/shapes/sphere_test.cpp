#include "scene/shapes/sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

Sphere unitSphere() { return Sphere(Vec3(0.0f), 1.0f, 0); }

TEST(Sphere, HitsTheNearSideWithTheOutwardNormal) {
  const Sphere sphere(Vec3(1.0f, 2.0f, 3.0f), 2.0f, 0);
  const auto result = intersect(sphere, Ray{{1.0f, 2.0f, -7.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 8.0f, {1.0f, 2.0f, 1.0f}, {0.0f, 0.0f, -1.0f}));
  EXPECT_EQ(result.hit.shape, &sphere);
}

TEST(Sphere, HitsOffCentre) {
  // x = 0.6 meets the unit sphere at z = -0.8.
  const auto result = intersect(unitSphere(), Ray{{0.6f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 4.2f, {0.6f, 0.0f, -0.8f}, {0.6f, 0.0f, -0.8f}));
}

TEST(Sphere, MissesARayPassingBeside) {
  EXPECT_TRUE(misses(intersect(unitSphere(), Ray{{0.0f, 1.5f, -5.0f}, {0.0f, 0.0f, 1.0f}})));
}

TEST(Sphere, MissesASphereBehindTheRay) {
  EXPECT_TRUE(misses(intersect(unitSphere(), Ray{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f}})));
}

TEST(Sphere, ATangentRayTouchesAtOnePoint) {
  const auto result = intersect(unitSphere(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
  EXPECT_TRUE(misses(intersect(unitSphere(), Ray{{-5.0f, 1.001f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
}

TEST(Sphere, ARayFromInsideExitsWithTheOutwardNormal) {
  const auto result = intersect(unitSphere(), Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 1.0f, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(Sphere, TMinExcludesTheNearRoot) {
  const auto result =
      intersect(unitSphere(), Ray{{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}, /*tMin=*/4.5f);
  EXPECT_TRUE(hitsAt(result, 6.0f, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(Sphere, ANearerHitAlreadyFoundIsKept) {
  const float nearer = 3.9f;
  const auto result =
      intersect(unitSphere(), Ray{{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}, 0.0f, nearer);
  EXPECT_TRUE(misses(result, nearer));
}

TEST(Sphere, ANonUnitDirectionFindsTheSamePoint) {
  for (float length : {0.5f, 4.0f}) {
    const auto result = intersect(unitSphere(), Ray{{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, length}});
    EXPECT_TRUE(hitsAt(result, 4.0f / length, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -1.0f}));
  }
}

TEST(Sphere, StaysPreciseFarFromTheRayOrigin) {
  // The textbook discriminant b^2 - ac cancels to 0 here in single precision
  // and puts the hit at 10000.
  const Sphere far(Vec3(0.0f, 0.0f, -1e4f), 1.0f, 0);
  const auto result = intersect(far, Ray{{0.0f, 0.5f, 0.0f}, {0.0f, 0.0f, -1.0f}});
  ASSERT_TRUE(result.found);
  EXPECT_NEAR(result.hit.t, 1e4f - std::sqrt(0.75f), 2e-3f);
}

TEST(Sphere, CountsOneTestPerRayHitOrMiss) {
  EXPECT_EQ(intersect(unitSphere(), Ray{{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}).counters.tests,
            1u);
  EXPECT_EQ(intersect(unitSphere(), Ray{{0.0f, 5.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}).counters.tests,
            1u);
}

}  // namespace
}  // namespace rise
