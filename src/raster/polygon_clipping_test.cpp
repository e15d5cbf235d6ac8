#include "raster/polygon_clipping.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace rise {
namespace {

TEST(PolygonClipping, SplitsASquareAlongADiagonalPlane) {
  const std::vector<Vec3> square = {Vec3(0.0f), Vec3(2.0f, 0.0f, 0.0f), Vec3(2.0f, 2.0f, 0.0f),
                                    Vec3(0.0f, 2.0f, 0.0f)};
  // x + y - 2 = 0 runs through two opposite corners; x - 1 = 0 through the middle.
  std::vector<Vec3> positive, negative;
  splitPolygon(square, glm::vec4(1.0f, 0.0f, 0.0f, -1.0f), 0.0f, positive, negative);
  ASSERT_EQ(positive.size(), 4u);
  ASSERT_EQ(negative.size(), 4u);
  for (const Vec3& corner : positive) EXPECT_GE(corner.x, 1.0f);
  for (const Vec3& corner : negative) EXPECT_LE(corner.x, 1.0f);

  splitPolygon(square, glm::vec4(1.0f, 1.0f, 0.0f, -2.0f), 0.0f, positive, negative);
  EXPECT_EQ(positive.size(), 3u);  // the corners on the plane belong to both
  EXPECT_EQ(negative.size(), 3u);
}

TEST(PolygonClipping, LeavesAPolygonOnOneSideWhole) {
  const std::vector<Vec3> triangle = {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
  std::vector<Vec3> positive, negative;
  splitPolygon(triangle, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f), 0.0f, positive, negative);
  EXPECT_EQ(positive, triangle);
  EXPECT_TRUE(negative.empty());
}

// Two polygons sharing an edge, running along it in opposite directions,
// must cut it at the very same point.
TEST(PolygonClipping, CutsASharedEdgeAtOnePoint) {
  const Vec3 a(0.1f, 0.3f, 0.7f), b(1.3f, -0.9f, 2.9f);
  const std::vector<Vec3> first = {a, b, Vec3(0.0f, 2.0f, 1.0f)};
  const std::vector<Vec3> second = {b, a, Vec3(2.0f, 0.0f, 1.0f)};
  const glm::vec4 plane(0.3f, 0.7f, 1.1f, -1.7f);
  std::vector<Vec3> positive1, negative1, positive2, negative2;
  splitPolygon(first, plane, 0.0f, positive1, negative1);
  splitPolygon(second, plane, 0.0f, positive2, negative2);
  const auto onEdge = [&](const std::vector<Vec3>& corners) {
    for (const Vec3& corner : corners)
      if (std::abs(signedDistance(plane, corner)) < 1e-5f &&
          glm::length(glm::cross(corner - a, b - a)) < 1e-4f)
        return corner;
    return Vec3(kInfinity);
  };
  ASSERT_NE(onEdge(positive1), Vec3(kInfinity));
  EXPECT_EQ(onEdge(positive1), onEdge(positive2));
}

}  // namespace
}  // namespace rise
