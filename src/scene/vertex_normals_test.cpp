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

TEST(VertexNormals, ATriangleWithoutAreaGetsNoNormal) {
  const MeshGeometry sliver = withVertexNormals(
      MeshGeometry{
          {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(2.0f, 0.0f, 0.0f)}, {}, {}, {{0, 1, 2}}},
      80.0f);
  EXPECT_EQ(sliver.normals[0], Vec3(0.0f));
}

}  // namespace
}  // namespace rise
