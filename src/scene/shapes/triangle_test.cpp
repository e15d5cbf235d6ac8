#include "scene/shapes/triangle.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

// Counter-clockwise seen from +z.
Triangle corner() {
  return Triangle({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)}, 0);
}

Ray downAt(float x, float y) { return Ray{{x, y, 5.0f}, {0.0f, 0.0f, -1.0f}}; }

TEST(Triangle, HitsWithTheWindingNormalAndBarycentrics) {
  const Triangle triangle = corner();
  const auto result = intersect(triangle, downAt(0.5f, 0.25f));
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.5f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(result.hit.shape, &triangle);
  EXPECT_FLOAT_EQ(result.hit.barycentric.x, 0.5f);
  EXPECT_FLOAT_EQ(result.hit.barycentric.y, 0.25f);
}

TEST(Triangle, HitsFromBehindWithTheSameNormal) {
  const auto result = intersect(corner(), Ray{{0.25f, 0.25f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(Triangle, ClockwiseWindingTurnsTheNormal) {
  const Triangle clockwise({Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f)}, 0);
  const auto result = intersect(clockwise, downAt(0.25f, 0.25f));
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(Triangle, MissesBeyondEachEdge) {
  EXPECT_TRUE(misses(intersect(corner(), downAt(-0.1f, 0.5f))));
  EXPECT_TRUE(misses(intersect(corner(), downAt(0.5f, -0.1f))));
  EXPECT_TRUE(misses(intersect(corner(), downAt(0.6f, 0.6f))));
}

TEST(Triangle, ItsEdgesAndVerticesBelongToIt) {
  EXPECT_TRUE(hitsAt(intersect(corner(), downAt(0.5f, 0.0f)), 5.0f, {0.5f, 0.0f, 0.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(hitsAt(intersect(corner(), downAt(0.0f, 1.0f)), 5.0f, {0.0f, 1.0f, 0.0f},
                     {0.0f, 0.0f, 1.0f}));
}

TEST(Triangle, ARayInItsPlaneMissesIt) {
  EXPECT_TRUE(misses(intersect(corner(), Ray{{-1.0f, 0.25f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
}

TEST(Triangle, TMinExcludesTheSurfaceARayLeaves) {
  EXPECT_TRUE(
      misses(intersect(corner(), Ray{{0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}}, kRayEpsilon)));
}

TEST(Triangle, ANearerHitAlreadyFoundIsKept) {
  EXPECT_TRUE(misses(intersect(corner(), downAt(0.25f, 0.25f), 0.0f, 4.0f), 4.0f));
}

TEST(Triangle, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(corner(), Ray{{0.25f, 0.25f, 5.0f}, {0.0f, 0.0f, -0.25f}});
  EXPECT_TRUE(hitsAt(result, 20.0f, {0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(Triangle, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(corner(), downAt(0.25f, 0.25f)).counters.tests, 1u);
  EXPECT_EQ(intersect(corner(), downAt(2.0f, 2.0f)).counters.tests, 1u);
}

}  // namespace
}  // namespace rise
