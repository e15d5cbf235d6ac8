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

// A cone of `slices` sides around the z axis, its apex at (0, 0, 1) shared by
// all its sides, and how high it is against its radius of 1.
MeshGeometry cone(int slices, float height) {
  MeshGeometry mesh;
  mesh.positions.push_back(Vec3(0.0f, 0.0f, height));
  for (int i = 0; i < slices; ++i) {
    const float angle = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
    mesh.positions.push_back(Vec3(std::cos(angle), std::sin(angle), 0.0f));
    mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % slices});
  }
  return mesh;
}

// A steep cone's sides face every way around it: each corner at the apex
// smooths with the sides within the crease angle of its own and not with
// those beyond it, however many sides meet there.
TEST(VertexNormals, EachCornerWhereThousandsOfTrianglesMeetSmoothsWithItsOwnNeighbours) {
  const MeshGeometry steep = cone(3000, 20.0f);
  const MeshGeometry smooth = withVertexNormals(steep, 80.0f);
  std::vector<Vec3> weighted;
  for (const auto& [a, b, c] : steep.triangles)
    weighted.push_back(glm::cross(steep.positions[b] - steep.positions[a],
                                  steep.positions[c] - steep.positions[a]));
  const float smoothCosine = std::cos(radians(80.0f));
  for (std::size_t triangle = 0; triangle < steep.triangles.size(); triangle += 97) {
    Vec3 expected(0.0f);
    for (const Vec3& other : weighted)
      if (glm::dot(glm::normalize(weighted[triangle]), glm::normalize(other)) >= smoothCosine)
        expected += other;
    const int apex = smooth.triangles[triangle][0];
    EXPECT_EQ(smooth.positions[apex], steep.positions[0]);
    EXPECT_TRUE(nearlyEqual(smooth.normals[apex], glm::normalize(expected)))
        << "the apex's corner of triangle " << triangle;
  }
  EXPECT_EQ(smooth.positions.size(), 2u * 3000u) << "the apex once for each side's normal";
}

TEST(VertexNormals, AFlatFanIsOneNormalAndAPointOfSliversNone) {
  MeshGeometry fan = cone(3000, 0.0f);
  MeshGeometry smooth = withVertexNormals(fan, 80.0f);
  EXPECT_EQ(smooth.positions.size(), fan.positions.size());
  for (const Vec3& normal : smooth.normals) EXPECT_TRUE(nearlyEqual(normal, {0.0f, 0.0f, 1.0f}));
  fan.positions.assign(fan.positions.size(), Vec3(1.0f, 2.0f, 3.0f));
  smooth = withVertexNormals(fan, 80.0f);
  EXPECT_EQ(smooth.positions.size(), fan.positions.size());
  for (const Vec3& normal : smooth.normals) EXPECT_EQ(normal, Vec3(0.0f));
}

}  // namespace
}  // namespace rise
