#include "scene/shapes/box.hpp"

#include <gtest/gtest.h>

#include <set>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

Box cube() { return Box(Vec3(-1.0f), Vec3(1.0f), 0); }

TEST(Box, HitsEachFaceWithItsOwnNormal) {
  const Box box = cube();
  std::set<int> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      Vec3 outward(0.0f);
      outward[axis] = side;
      const auto result = intersect(box, Ray{5.0f * outward, -outward});
      EXPECT_TRUE(hitsAt(result, 4.0f, outward, outward)) << "axis " << axis << " side " << side;
      EXPECT_EQ(result.hit.shape, &box);
      faces.insert(result.hit.primitive);
    }
  }
  EXPECT_EQ(faces.size(), 6u);
}

TEST(Box, TakesAnyTwoOppositeCorners) {
  const Box box(Vec3(1.0f, -1.0f, 2.0f), Vec3(-1.0f, 3.0f, 0.0f), 0);
  const auto result = intersect(box, Ray{{0.0f, 1.0f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(Box, EntersWhereTheLastSlabIsEntered) {
  // Along (1, 1, 0) from (-3, -2, 0): into the y slab at t = 1, the x slab at t = 2.
  const auto result = intersect(cube(), Ray{{-3.0f, -2.0f, 0.0f}, {1.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 2.0f, {-1.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}));
}

TEST(Box, MissesARayPassingBeside) {
  EXPECT_TRUE(misses(intersect(cube(), Ray{{-5.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
  // Out of the y slab (t = 1) before it is in the x slab (t = 2).
  EXPECT_TRUE(misses(intersect(cube(), Ray{{-3.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}})));
}

TEST(Box, MissesABoxBehindTheRay) {
  EXPECT_TRUE(misses(intersect(cube(), Ray{{-5.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}})));
}

TEST(Box, ARayAlongAFaceTouchesItAndEntersByTheFaceAhead) {
  const auto result = intersect(cube(), Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.0f, {-1.0f, 1.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}));
}

TEST(Box, ARayFromInsideExitsWithTheOutwardNormal) {
  const auto up = intersect(cube(), Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(up, 1.0f, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
  const auto down = intersect(cube(), Ray{{0.0f, 0.0f, 0.0f}, {0.0f, -2.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(down, 0.5f, {0.0f, -1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}));
}

TEST(Box, TMinExcludesTheEntry) {
  const auto result =
      intersect(cube(), Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, /*tMin=*/4.5f);
  EXPECT_TRUE(hitsAt(result, 6.0f, {1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}));
}

TEST(Box, ANearerHitAlreadyFoundIsKept) {
  EXPECT_TRUE(
      misses(intersect(cube(), Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, 0.0f, 3.0f), 3.0f));
}

TEST(Box, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(cube(), Ray{{-5.0f, 0.5f, 0.25f}, {8.0f, 0.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 0.5f, {-1.0f, 0.5f, 0.25f}, {-1.0f, 0.0f, 0.0f}));
}

TEST(Box, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(cube(), Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
  EXPECT_EQ(intersect(cube(), Ray{{-5.0f, 5.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests, 1u);
}

}  // namespace
}  // namespace rise
