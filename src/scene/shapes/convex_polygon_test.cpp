#include "scene/shapes/convex_polygon.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

// A house in z = 0, counter-clockwise seen from +z: the square [0, 2]^2 with a
// roof up to (1, 3).
std::vector<Vec3> houseOutline() {
  return {Vec3(0.0f), Vec3(2.0f, 0.0f, 0.0f), Vec3(2.0f, 2.0f, 0.0f), Vec3(1.0f, 3.0f, 0.0f),
          Vec3(0.0f, 2.0f, 0.0f)};
}

ConvexPolygon house() { return ConvexPolygon(houseOutline(), 0); }

Ray downAt(float x, float y) { return Ray{{x, y, 5.0f}, {0.0f, 0.0f, -1.0f}}; }

TEST(IsPlanarConvexPolygon, AcceptsConvexPolygonsEitherWay) {
  EXPECT_TRUE(isPlanarConvexPolygon(houseOutline()));
  std::vector<Vec3> clockwise = houseOutline();
  std::reverse(clockwise.begin(), clockwise.end());
  EXPECT_TRUE(isPlanarConvexPolygon(clockwise));
  EXPECT_TRUE(isPlanarConvexPolygon(
      {Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)}));
}

TEST(IsPlanarConvexPolygon, ToleratesRoundingAtAnyScale) {
  std::vector<Vec3> large = houseOutline();
  for (Vec3& v : large) v = 1000.0f * v + Vec3(0.0f, 0.0f, 500.0f);
  large[3].z += 1e-3f;
  EXPECT_TRUE(isPlanarConvexPolygon(large));
}

TEST(IsPlanarConvexPolygon, RejectsTooFewCollinearOrNonFiniteVertices) {
  EXPECT_FALSE(isPlanarConvexPolygon({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f)}));
  EXPECT_FALSE(isPlanarConvexPolygon(
      {Vec3(0.0f), Vec3(1.0f, 1.0f, 1.0f), Vec3(2.0f, 2.0f, 2.0f), Vec3(3.0f, 3.0f, 3.0f)}));
  EXPECT_FALSE(isPlanarConvexPolygon({Vec3(1.0f), Vec3(1.0f), Vec3(1.0f)}));
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), kInfinity}) {
    std::vector<Vec3> outline = houseOutline();
    outline[2].y = bad;
    EXPECT_FALSE(isPlanarConvexPolygon(outline)) << bad;
  }
}

TEST(IsPlanarConvexPolygon, RejectsAWarpedOutline) {
  std::vector<Vec3> warped = houseOutline();
  warped[3].z = 0.1f;
  EXPECT_FALSE(isPlanarConvexPolygon(warped));
}

TEST(IsPlanarConvexPolygon, RejectsAConcaveOutline) {
  std::vector<Vec3> dented = houseOutline();
  dented[3].y = 1.0f;  // the roof pushed in below the eaves
  EXPECT_FALSE(isPlanarConvexPolygon(dented));
}

TEST(IsPlanarConvexPolygon, RejectsAStarWhoseTurnsAllGoOneWay) {
  std::vector<Vec3> pentagram;
  for (int i = 0; i < 5; ++i) {
    const float angle = radians(144.0f * static_cast<float>(i));
    pentagram.emplace_back(std::cos(angle), std::sin(angle), 0.0f);
  }
  EXPECT_FALSE(isPlanarConvexPolygon(pentagram));
}

TEST(ConvexPolygon, HitsInsideWithTheWindingNormal) {
  const ConvexPolygon polygon = house();
  const auto result = intersect(polygon, downAt(1.0f, 2.5f));
  EXPECT_TRUE(hitsAt(result, 5.0f, {1.0f, 2.5f, 0.0f}, {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(result.hit.shape, &polygon);
}

TEST(ConvexPolygon, ClockwiseWindingTurnsTheNormal) {
  std::vector<Vec3> clockwise = houseOutline();
  std::reverse(clockwise.begin(), clockwise.end());
  const auto result = intersect(ConvexPolygon(clockwise, 0), downAt(1.0f, 1.0f));
  EXPECT_TRUE(hitsAt(result, 5.0f, {1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(ConvexPolygon, HitsAPolygonInATiltedPlane) {
  const ConvexPolygon slanted(
      {Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)}, 0);
  const auto result = intersect(slanted, Ray{Vec3(0.0f), Vec3(1.0f)});
  EXPECT_TRUE(hitsAt(result, 1.0f / 3.0f, Vec3(1.0f / 3.0f), Vec3(1.0f / std::sqrt(3.0f))));
}

TEST(ConvexPolygon, MissesOutsideEvenWithinItsBounds) {
  EXPECT_TRUE(misses(intersect(house(), downAt(1.9f, 2.9f))));
  EXPECT_TRUE(misses(intersect(house(), downAt(3.0f, 1.0f))));
}

TEST(ConvexPolygon, ItsEdgesBelongToIt) {
  EXPECT_TRUE(
      hitsAt(intersect(house(), downAt(2.0f, 1.0f)), 5.0f, {2.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(ConvexPolygon, ARayInItsPlaneMissesIt) {
  EXPECT_TRUE(misses(intersect(house(), Ray{{-1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})));
}

TEST(ConvexPolygon, TMinAndTheNearerHitBoundTheSearch) {
  EXPECT_TRUE(misses(intersect(house(), Ray{{1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}, kRayEpsilon)));
  EXPECT_TRUE(misses(intersect(house(), downAt(1.0f, 1.0f), 0.0f, 4.0f), 4.0f));
}

TEST(ConvexPolygon, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(house(), Ray{{1.0f, 1.0f, 5.0f}, {0.0f, 0.0f, -2.0f}});
  EXPECT_TRUE(hitsAt(result, 2.5f, {1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}));
}

TEST(ConvexPolygon, CountsOneTestPerRay) {
  EXPECT_EQ(intersect(house(), downAt(1.0f, 1.0f)).counters.tests, 1u);
  EXPECT_EQ(intersect(house(), downAt(9.0f, 9.0f)).counters.tests, 1u);
}

}  // namespace
}  // namespace rise
