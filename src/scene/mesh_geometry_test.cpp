#include "scene/mesh_geometry.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

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

}  // namespace
}  // namespace rise
