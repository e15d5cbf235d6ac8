#include "scene/shapes/cone.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;
using shape_testing::tilted;

// Base radius 1 at y = 0, apex at y = 2; the axis is given at three times unit
// length. Its radius at height y is 1 - y / 2, and the outward normal of its
// side leans up by as much as the side leans in: (2 r + y-axis) / sqrt(5) for
// the horizontal unit vector r.
Cone upright() { return Cone(Vec3(0.0f), Vec3(0.0f, 3.0f, 0.0f), 1.0f, 2.0f, 0); }

Vec3 sideNormal(float rx, float rz) { return Vec3(2.0f * rx, 1.0f, 2.0f * rz) / std::sqrt(5.0f); }

TEST(Cone, HitsTheSide) {
  const Cone cone = upright();
  const auto result = intersect(cone, Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.5f, {-0.5f, 1.0f, 0.0f}, sideNormal(-1.0f, 0.0f)));
  EXPECT_EQ(result.hit.shape, &cone);
}

TEST(Cone, HitsTheBase) {
  const auto result = intersect(upright(), Ray{{0.25f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.25f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}));
}

TEST(Cone, MissesTheOtherNappeAndBeside) {
  // Above the apex the ray crosses the quadric's other nappe, not the cone.
  EXPECT_TRUE(misses(intersect(upright(), Ray{{-5.0f, 3.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
  EXPECT_TRUE(misses(intersect(upright(), Ray{{-5.0f, 1.0f, 0.6f}, {1.0f, 0.0f, 0.0f}})));
  EXPECT_TRUE(misses(intersect(upright(), Ray{{1.5f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}})));
}

TEST(Cone, ATangentRayTouchesTheSide) {
  const auto result = intersect(upright(), Ray{{-0.5f, 1.0f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {-0.5f, 1.0f, 0.0f}, sideNormal(-1.0f, 0.0f)));
}

TEST(Cone, TheApexTakesTheAxisAsItsNormal) {
  const auto result = intersect(upright(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 3.0f, {0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Cone, ARayFromInsideExitsWithTheOutwardNormal) {
  const auto side = intersect(upright(), Ray{{0.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(side, 0.75f, {0.75f, 0.5f, 0.0f}, sideNormal(1.0f, 0.0f)));
  const auto base = intersect(upright(), Ray{{0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(base, 1.0f, {0.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}));
}

TEST(Cone, TMinExcludesTheNearSide) {
  const auto result =
      intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, /*tMin=*/4.6f);
  EXPECT_TRUE(hitsAt(result, 5.5f, {0.5f, 1.0f, 0.0f}, sideNormal(1.0f, 0.0f)));
}

TEST(Cone, ANearerHitAlreadyFoundIsKept) {
  EXPECT_TRUE(
      misses(intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, 0.0f, 4.0f), 4.0f));
}

TEST(Cone, ANonUnitDirectionFindsTheSamePoint) {
  const auto side = intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {9.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(side, 0.5f, {-0.5f, 1.0f, 0.0f}, sideNormal(-1.0f, 0.0f)));
  const auto base = intersect(upright(), Ray{{0.25f, -5.0f, 0.0f}, {0.0f, 0.5f, 0.0f}});
  EXPECT_TRUE(hitsAt(base, 10.0f, {0.25f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}));
}

TEST(Cone, ATiltedAxisTurnsEveryAnswer) {
  const Cone cone(Vec3(0.0f), tilted({0.0f, 1.0f, 0.0f}), 1.0f, 2.0f, 0);
  const auto side = intersect(cone, Ray{tilted({-5.0f, 1.0f, 0.0f}), tilted({1.0f, 0.0f, 0.0f})});
  EXPECT_TRUE(hitsAt(side, 4.5f, tilted({-0.5f, 1.0f, 0.0f}), tilted(sideNormal(-1.0f, 0.0f))));
  const auto base = intersect(cone, Ray{tilted({0.25f, -5.0f, 0.0f}), tilted({0.0f, 1.0f, 0.0f})});
  EXPECT_TRUE(hitsAt(base, 5.0f, tilted({0.25f, 0.0f, 0.0f}), tilted({0.0f, -1.0f, 0.0f})));
}

TEST(Cone, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
  EXPECT_EQ(intersect(upright(), Ray{{-5.0f, 9.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
}

}  // namespace
}  // namespace rise
