#include "scene/mesh_geometry.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

// A triangle in the plane x + y = 1, its normals (1, 1, 0) / sqrt(2) facing
// the side its winding turns counter-clockwise around.
MeshGeometry slantedTriangle() {
  const Vec3 normal = glm::normalize(Vec3(1.0f, 1.0f, 0.0f));
  return MeshGeometry{{Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 1.0f)},
                      {normal, normal, normal},
                      {},
                      {{0, 1, 2}}};
}

TEST(MeshGeometry, TransformsPositionsAndNormalsByTheInverseTranspose) {
  // Stretched 2 along x, the plane becomes x / 2 + y = 1, with the normal (1, 2, 0) / sqrt(5).
  const MeshGeometry stretched =
      transformed(slantedTriangle(), glm::scale(Mat4(1.0f), Vec3(2.0f, 1.0f, 1.0f)));
  EXPECT_TRUE(nearlyEqual(stretched.positions[0], {2.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(stretched.positions[2], {2.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearlyEqual(stretched.normals[1], glm::normalize(Vec3(1.0f, 2.0f, 0.0f))));
  EXPECT_EQ(stretched.triangles[0], (std::array<int, 3>{0, 1, 2}));
}

TEST(MeshGeometry, AMirrorReversesTheWindingSoThatItStillFacesTheNormals) {
  const MeshGeometry mirrored =
      transformed(slantedTriangle(), glm::scale(Mat4(1.0f), Vec3(-1.0f, 1.0f, 1.0f)));
  EXPECT_TRUE(nearlyEqual(mirrored.normals[0], glm::normalize(Vec3(-1.0f, 1.0f, 0.0f))));
  const auto& [a, b, c] = mirrored.triangles[0];
  const Vec3 winding = glm::cross(mirrored.positions[b] - mirrored.positions[a],
                                  mirrored.positions[c] - mirrored.positions[a]);
  EXPECT_GT(glm::dot(winding, mirrored.normals[0]), 0.0f);
}

TEST(MeshGeometry, AppendingShiftsTheIndicesAndPadsMissingAttributes) {
  MeshGeometry whole{{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)},
                     {},
                     {Vec2(0.5f), Vec2(0.5f), Vec2(0.5f)},
                     {{0, 1, 2}}};
  append(whole, slantedTriangle());
  ASSERT_EQ(whole.positions.size(), 6u);
  EXPECT_EQ(whole.triangles[1], (std::array<int, 3>{3, 4, 5}));
  ASSERT_EQ(whole.normals.size(), 6u);
  EXPECT_EQ(whole.normals[0], Vec3(0.0f));
  EXPECT_TRUE(nearlyEqual(whole.normals[3], glm::normalize(Vec3(1.0f, 1.0f, 0.0f))));
  ASSERT_EQ(whole.uvs.size(), 6u);
  EXPECT_EQ(whole.uvs[2], Vec2(0.5f));
  EXPECT_EQ(whole.uvs[5], Vec2(0.0f));
}

TEST(MeshGeometry, JoiningKeepsOneVertexForEachSetOfAttributesInTheOrderTheyFirstAppear) {
  // A square as a reader gives it, a vertex for each corner of each face; the
  // top-right corner seen by the second face has other texture coordinates.
  const Vec3 a(0.0f), b(1.0f, 0.0f, 0.0f), c(1.0f, 1.0f, 0.0f), d(0.0f, 1.0f, 0.0f);
  const MeshGeometry corners{
      {b, a, c, c, a, d},
      {},
      {Vec2(1, 0), Vec2(0, 0), Vec2(1, 1), Vec2(9, 9), Vec2(0, 0), Vec2(0, 1)},
      {{0, 1, 2}, {3, 4, 5}}};
  const MeshGeometry joined = withIdenticalVerticesJoined(corners);
  EXPECT_EQ(joined.positions, (std::vector<Vec3>{b, a, c, c, d}));
  EXPECT_EQ(joined.uvs,
            (std::vector<Vec2>{Vec2(1, 0), Vec2(0, 0), Vec2(1, 1), Vec2(9, 9), Vec2(0, 1)}));
  EXPECT_TRUE(joined.normals.empty());
  EXPECT_EQ(joined.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {3, 1, 4}}));
}

TEST(MeshGeometry, JoiningTellsVerticesApartByTheirNormalsAndKeepsThoseThatAreNotNumbers) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Vec3 p(1.0f, 2.0f, 3.0f), up(0.0f, 1.0f, 0.0f), side(1.0f, 0.0f, 0.0f);
  const MeshGeometry corners{
      {p, p, p, Vec3(nan), Vec3(nan), p}, {up, side, up, up, up, up}, {}, {{0, 1, 2}, {3, 4, 5}}};
  const MeshGeometry joined = withIdenticalVerticesJoined(corners);
  ASSERT_EQ(joined.positions.size(), 3u);  // p facing up, p facing aside, the one not a number
  EXPECT_EQ(joined.normals, (std::vector<Vec3>{up, side, up}));
  EXPECT_EQ(joined.triangles, (std::vector<std::array<int, 3>>{{0, 1, 0}, {2, 2, 0}}));
}

}  // namespace
}  // namespace rise
