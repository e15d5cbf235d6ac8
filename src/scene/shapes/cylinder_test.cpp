#include "scene/shapes/cylinder.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;
using shape_testing::tilted;

// Radius 1, from y = 0 to y = 2; the axis is given at twice unit length.
Cylinder upright() { return Cylinder(Vec3(0.0f), Vec3(0.0f, 2.0f, 0.0f), 1.0f, 2.0f, 0); }

TEST(Cylinder, HitsTheSide) {
  const Cylinder cylinder = upright();
  const auto result = intersect(cylinder, Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.0f, {-1.0f, 1.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}));
  EXPECT_EQ(result.hit.shape, &cylinder);
}

TEST(Cylinder, HitsTheSideOffCentre) {
  // z = 0.6 meets the side at x = -0.8.
  const auto result = intersect(upright(), Ray{{-5.0f, 1.0f, 0.6f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.2f, {-0.8f, 1.0f, 0.6f}, {-0.8f, 0.0f, 0.6f}));
}

TEST(Cylinder, HitsBothCaps) {
  const auto top = intersect(upright(), Ray{{0.5f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(top, 3.0f, {0.5f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
  const auto base = intersect(upright(), Ray{{0.5f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(base, 5.0f, {0.5f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}));
}

TEST(Cylinder, HitsTheCapObliquely) {
  const auto result = intersect(upright(), Ray{{0.0f, 4.0f, 0.0f}, {0.25f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 2.0f, {0.5f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Cylinder, MissesBesideAboveAndAlongTheAxisOutside) {
  EXPECT_TRUE(misses(intersect(upright(), Ray{{-5.0f, 1.0f, 1.5f}, {1.0f, 0.0f, 0.0f}})));
  EXPECT_TRUE(misses(intersect(upright(), Ray{{-5.0f, 3.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
  EXPECT_TRUE(misses(intersect(upright(), Ray{{1.5f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}})));
}

TEST(Cylinder, ATangentRayTouchesTheSide) {
  const auto result = intersect(upright(), Ray{{-5.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.0f, 1.0f, 1.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(Cylinder, ARayFromInsideExitsWithTheOutwardNormal) {
  const auto side = intersect(upright(), Ray{{0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(side, 1.0f, {1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}));
  const auto cap = intersect(upright(), Ray{{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(cap, 1.0f, {0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Cylinder, TMinExcludesTheNearSide) {
  const auto result =
      intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, /*tMin=*/4.5f);
  EXPECT_TRUE(hitsAt(result, 6.0f, {1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}));
}

TEST(Cylinder, ANearerHitAlreadyFoundIsKept) {
  EXPECT_TRUE(
      misses(intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, 0.0f, 3.0f), 3.0f));
  EXPECT_TRUE(
      misses(intersect(upright(), Ray{{0.5f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, 0.0f, 2.5f), 2.5f));
}

TEST(Cylinder, ANonUnitDirectionFindsTheSamePoint) {
  const auto side = intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {4.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(side, 1.0f, {-1.0f, 1.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}));
  const auto cap = intersect(upright(), Ray{{0.5f, 5.0f, 0.0f}, {0.0f, -0.5f, 0.0f}});
  EXPECT_TRUE(hitsAt(cap, 6.0f, {0.5f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Cylinder, ATiltedAxisTurnsEveryAnswer) {
  const Cylinder cylinder(Vec3(0.0f), tilted({0.0f, 1.0f, 0.0f}), 1.0f, 2.0f, 0);
  const auto side =
      intersect(cylinder, Ray{tilted({-5.0f, 1.0f, 0.0f}), tilted({1.0f, 0.0f, 0.0f})});
  EXPECT_TRUE(hitsAt(side, 4.0f, tilted({-1.0f, 1.0f, 0.0f}), tilted({-1.0f, 0.0f, 0.0f})));
  const auto top =
      intersect(cylinder, Ray{tilted({0.5f, 5.0f, 0.0f}), tilted({0.0f, -1.0f, 0.0f})});
  EXPECT_TRUE(hitsAt(top, 3.0f, tilted({0.5f, 2.0f, 0.0f}), tilted({0.0f, 1.0f, 0.0f})));
  const auto base =
      intersect(cylinder, Ray{tilted({0.5f, -5.0f, 0.0f}), tilted({0.0f, 1.0f, 0.0f})});
  EXPECT_TRUE(hitsAt(base, 5.0f, tilted({0.5f, 0.0f, 0.0f}), tilted({0.0f, -1.0f, 0.0f})));
}

TEST(Cylinder, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(upright(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
  EXPECT_EQ(intersect(upright(), Ray{{-5.0f, 9.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
}

}  // namespace
}  // namespace rise
