#include "scene/shapes/plane.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

// The plane y = 1, given a normal that is not unit length.
Plane planeYIsOne() { return Plane(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 2.0f, 0.0f), 0); }

TEST(Plane, HitsFromAboveWithTheGivenNormal) {
  const Plane plane = planeYIsOne();
  const auto result = intersect(plane, Ray{{3.0f, 5.0f, -2.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.0f, {3.0f, 1.0f, -2.0f}, {0.0f, 1.0f, 0.0f}));
  EXPECT_EQ(result.hit.shape, &plane);
}

TEST(Plane, HitsFromBehindWithTheSameNormal) {
  const auto result = intersect(planeYIsOne(), Ray{{0.0f, -3.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 4.0f, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Plane, HitsAnObliqueNonUnitRay) {
  const auto result = intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {1.0f, -2.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 2.0f, {2.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Plane, MissesAParallelRayAndOneLyingInIt) {
  EXPECT_TRUE(misses(intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
  EXPECT_TRUE(misses(intersect(planeYIsOne(), Ray{{0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
}

TEST(Plane, MissesARayGoingAway) {
  EXPECT_TRUE(misses(intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}})));
}

TEST(Plane, TMinExcludesTheSurfaceARayLeaves) {
  const auto result =
      intersect(planeYIsOne(), Ray{{0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, kRayEpsilon);
  EXPECT_TRUE(misses(result));
}

TEST(Plane, ANearerHitAlreadyFoundIsKept) {
  EXPECT_TRUE(misses(
      intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, 0.0f, 3.0f), 3.0f));
}

TEST(Plane, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -8.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 0.5f, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(Plane, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}).counters.tests,
            1u);
  EXPECT_EQ(intersect(planeYIsOne(), Ray{{0.0f, 5.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}).counters.tests,
            1u);
}

// The floor's texture coordinates are u = x, v = -z, measured from its point.
TEST(Plane, FloorTextureCoordinatesAreXAndMinusZ) {
  const auto result = intersect(planeYIsOne(), Ray{{3.0f, 5.0f, -2.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_FLOAT_EQ(result.surface.uv.x, 3.0f);
  EXPECT_FLOAT_EQ(result.surface.uv.y, 2.0f);
}

// A wall facing x gets its u axis from z.
TEST(Plane, WallFacingXTakesUFromZ) {
  const Plane wall(Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), 0);
  const auto result = intersect(wall, Ray{{5.0f, 2.0f, 3.0f}, {-1.0f, 0.0f, 0.0f}});
  EXPECT_FLOAT_EQ(result.surface.uv.x, 3.0f);
  EXPECT_FLOAT_EQ(result.surface.uv.y, -2.0f);
}

}  // namespace
}  // namespace rise
