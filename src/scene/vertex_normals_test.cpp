#include "scene/vertex_normals.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

// Two triangles that share the edge from (0, 0, 0) to (0, 1, 0) and fold
// along it by `foldDegrees`: the first lies in z = 0 facing +z, the second
// turns about the y axis.
MeshGeometry fold(float foldDegrees) {
  const float angle = radians(foldDegrees);
  return MeshGeometry{{Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(-1.0f, 0.0f, 0.0f),
                       Vec3(std::cos(angle), 0.0f, std::sin(angle))},
                      {},
                      {},
                      {{0, 1, 2}, {0, 3, 1}}};
}

TEST(VertexNormals, AGentleFoldIsSmoothedAlongItsEdge) {
  // Equal areas: the shared corners get the bisector of the two normals.
  const MeshGeometry smooth = withVertexNormals(fold(30.0f), 80.0f);
  ASSERT_EQ(smooth.triangles.size(), 2u);
  const Vec3 bisector(std::sin(radians(-15.0f)), 0.0f, std::cos(radians(15.0f)));
  EXPECT_TRUE(nearlyEqual(smooth.normals[smooth.triangles[0][0]], bisector));
  EXPECT_EQ(smooth.triangles[0][0], smooth.triangles[1][0]);
  // A corner that only one triangle has keeps that triangle's normal.
  EXPECT_TRUE(nearlyEqual(smooth.normals[smooth.triangles[0][2]], {0.0f, 0.0f, 1.0f}));
  EXPECT_EQ(smooth.positions.size(), 4u);
}

TEST(VertexNormals, ASharpFoldKeepsItsCreaseWithVerticesOfItsOwn) {
  const MeshGeometry creased = withVertexNormals(fold(90.0f), 80.0f);
  EXPECT_EQ(creased.positions.size(), 6u);
  EXPECT_TRUE(nearlyEqual(creased.normals[creased.triangles[0][0]], {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearlyEqual(creased.normals[creased.triangles[1][0]], {-1.0f, 0.0f, 0.0f}));
  EXPECT_EQ(creased.positions[creased.triangles[1][0]], Vec3(0.0f));
}

TEST(VertexNormals, VerticesAtOnePointSmoothTogetherAndKeepTheirTextureCoordinates) {
  // The fold with its shared edge split, as a seam of texture coordinates splits it.
  MeshGeometry seam = fold(30.0f);
  seam.positions.push_back(seam.positions[0]);
  seam.positions.push_back(seam.positions[1]);
  seam.triangles[1] = {4, 3, 5};
  seam.uvs = {Vec2(0.0f), Vec2(0.0f, 1.0f), Vec2(1.0f, 0.0f), Vec2(0.5f), Vec2(0.25f), Vec2(0.75f)};
  const MeshGeometry smooth = withVertexNormals(seam, 80.0f);
  EXPECT_TRUE(
      nearlyEqual(smooth.normals[smooth.triangles[0][0]], smooth.normals[smooth.triangles[1][0]]));
  EXPECT_EQ(smooth.uvs[smooth.triangles[1][0]], Vec2(0.25f));
}

// A fan of four triangles around the origin, each with a copy of the centre
// of its own, listed out of order, one as -0: the centre's corners all get
// the area-weighted average of the four normals.
TEST(VertexNormals, CopiesOfAPointInAnyOrderSmoothTogether) {
  const std::array<Vec3, 4> rim = {Vec3(1.0f, 0.0f, 0.2f), Vec3(0.0f, 1.0f, -0.1f),
                                   Vec3(-1.0f, 0.0f, 0.3f), Vec3(0.0f, -1.0f, 0.0f)};
  MeshGeometry fan;
  fan.positions.assign(rim.begin(), rim.end());
  fan.positions.insert(fan.positions.end(),
                       {Vec3(0.0f), Vec3(-0.0f, 0.0f, 0.0f), Vec3(0.0f), Vec3(0.0f)});
  Vec3 weighted(0.0f);
  for (int i = 0; i < 4; ++i) {
    fan.triangles.push_back({7 - i, i, (i + 1) % 4});
    weighted += glm::cross(rim[i], rim[(i + 1) % 4]);
  }
  const MeshGeometry smooth = withVertexNormals(fan, 80.0f);
  for (const auto& corners : smooth.triangles)
    EXPECT_TRUE(nearlyEqual(smooth.normals[corners[0]], glm::normalize(weighted)));
  EXPECT_EQ(smooth.positions.size(), 8u) << "each vertex once: no crease splits one";
}

TEST(VertexNormals, ATriangleWithoutAreaGetsNoNormal) {
  const MeshGeometry sliver = withVertexNormals(
      MeshGeometry{
          {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(2.0f, 0.0f, 0.0f)}, {}, {}, {{0, 1, 2}}},
      80.0f);
  EXPECT_EQ(sliver.normals[0], Vec3(0.0f));
}

}  // namespace
}  // namespace rise
