#include "scene/tessellation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "scene/mesh_geometry.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/shapes/vertex_attributes.hpp"
#include "scene/transform.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

Tessellation tessellate(const Shape& shape, int level = 4) {
  TessellationSettings settings;
  settings.level = level;
  settings.viewpoint = Vec3(3.0f, 5.0f, -7.0f);
  Tessellation tessellation;
  shape.tessellate(settings, tessellation);
  return tessellation;
}

std::vector<Vec3> positionsOf(const Tessellation& tessellation) {
  std::vector<Vec3> positions;
  for (const SurfaceVertex& vertex : tessellation.vertices) positions.push_back(vertex.position);
  return positions;
}

// Every triangle turns counter-clockwise around the normals at its corners:
// seen from outside, for a solid.
void expectWoundAroundItsNormals(const Tessellation& tessellation) {
  for (const auto& [a, b, c] : tessellation.triangles) {
    const SurfaceVertex& p = tessellation.vertices[a];
    const SurfaceVertex& q = tessellation.vertices[b];
    const SurfaceVertex& r = tessellation.vertices[c];
    const Vec3 winding = glm::cross(q.position - p.position, r.position - p.position);
    EXPECT_GT(glm::dot(winding, p.normal + q.normal + r.normal), 0.0f);
  }
}

void expectUnitNormals(const Tessellation& tessellation) {
  for (const SurfaceVertex& vertex : tessellation.vertices)
    EXPECT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f);
}

void expectClosedSolid(const Tessellation& tessellation) {
  EXPECT_TRUE(tessellation.enclosesSolid);
  EXPECT_TRUE(enclosesSolid(positionsOf(tessellation), tessellation.triangles));
  expectWoundAroundItsNormals(tessellation);
}

TEST(Tessellation, PutsASpheresVerticesOnItWithItsNormals) {
  const Vec3 centre(1.0f, -2.0f, 0.5f);
  const Tessellation sphere = tessellate(Sphere(centre, 1.5f, 0), 4);
  for (const SurfaceVertex& vertex : sphere.vertices) {
    EXPECT_NEAR(glm::length(vertex.position - centre), 1.5f, 1e-5f);
    EXPECT_NEAR(glm::length(vertex.normal - (vertex.position - centre) / 1.5f), 0.0f, 1e-5f);
  }
  // 16 segments around, 8 rings: quads between the rings, triangles at the poles.
  EXPECT_EQ(sphere.triangles.size(), 16u * 6u * 2u + 2u * 16u);
  expectClosedSolid(sphere);
  expectUnitNormals(sphere);
}

TEST(Tessellation, PutsACylindersVerticesOnItsSideAndCaps) {
  const Vec3 base(0.0f, 1.0f, 0.0f), axis = glm::normalize(Vec3(1.0f, 1.0f, 0.0f));
  const Tessellation cylinder = tessellate(Cylinder(base, axis, 0.5f, 2.0f, 0), 3);
  for (const SurfaceVertex& vertex : cylinder.vertices) {
    const Vec3 offset = vertex.position - base;
    const float along = glm::dot(offset, axis);
    EXPECT_NEAR(glm::length(offset - along * axis), 0.5f, 1e-5f);
    EXPECT_TRUE(std::abs(along) < 1e-5f || std::abs(along - 2.0f) < 1e-5f);
  }
  expectClosedSolid(cylinder);
  expectUnitNormals(cylinder);
}

TEST(Tessellation, PutsAConesVerticesOnItsSideAndBase) {
  const Vec3 base(0.0f), axis(0.0f, 1.0f, 0.0f);
  const Tessellation cone = tessellate(Cone(base, axis, 1.0f, 2.0f, 0), 3);
  for (const SurfaceVertex& vertex : cone.vertices) {
    const float height = vertex.position.y;
    const float radius = std::hypot(vertex.position.x, vertex.position.z);
    EXPECT_NEAR(radius, 1.0f - 0.5f * height, 1e-5f);
    // The side's normal leans up by atan(radius / height); it weighs as
    // much as the point is far from the axis, nothing at the apex.
    if (vertex.normal.y > 0.0f) {
      EXPECT_NEAR(glm::normalize(vertex.normal).y, 1.0f / std::sqrt(5.0f), 1e-5f);
      EXPECT_NEAR(glm::length(vertex.normal), radius, 1e-5f);
    }
  }
  expectClosedSolid(cone);
}

// Interpolated across any facet of the side, up to the apex, the corners'
// normals give the cone's own normal along the line from the rim through
// the point: the facets do not show.
TEST(Tessellation, InterpolatesAConesNormalsAsTheConesOwn) {
  const float radius = 0.8f, height = 1.5f;
  const Tessellation cone =
      tessellate(Cone(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), radius, height, 0), 2);
  int sidePoints = 0;
  for (const auto& [a, b, c] : cone.triangles) {
    const SurfaceVertex& p = cone.vertices[a];
    const SurfaceVertex& q = cone.vertices[b];
    const SurfaceVertex& r = cone.vertices[c];
    if (p.position.y == 0.0f && q.position.y == 0.0f && r.position.y == 0.0f) continue;  // base
    for (const Vec2 barycentric : {Vec2(0.1f, 0.1f), Vec2(0.8f, 0.1f), Vec2(0.1f, 0.8f),
                                   Vec2(0.45f, 0.45f), Vec2(0.02f, 0.03f), Vec2(0.97f, 0.01f)}) {
      const Vec3 position = atBarycentric(p.position, q.position, r.position, barycentric);
      const Vec3 flat =
          glm::normalize(glm::cross(q.position - p.position, r.position - p.position));
      const Vec3 normal = interpolatedNormal(flat, p.normal, q.normal, r.normal, barycentric);
      const Vec3 across = glm::normalize(Vec3(position.x, 0.0f, position.z));
      const Vec3 exact = glm::normalize(height * across + radius * Vec3(0.0f, 1.0f, 0.0f));
      // The facet's chord is 8 segments a turn here: its points lie
      // cos(pi / 8) as far from the axis as the cone's.
      EXPECT_GT(glm::dot(normal, exact), std::cos(0.05f)) << shape_testing::text(position);
      ++sidePoints;
    }
  }
  EXPECT_GT(sidePoints, 0);
}

TEST(Tessellation, CoversABoxWithTwoTrianglesAFace) {
  const Tessellation box = tessellate(Box(Vec3(-1.0f, 0.0f, 2.0f), Vec3(1.0f, 3.0f, 4.0f), 0));
  EXPECT_EQ(box.triangles.size(), 12u);
  for (const SurfaceVertex& vertex : box.vertices) {
    // On the face its normal names.
    const int axis = vertex.normal.x != 0.0f ? 0 : (vertex.normal.y != 0.0f ? 1 : 2);
    const float face =
        vertex.normal[axis] > 0.0f ? Vec3(1.0f, 3.0f, 4.0f)[axis] : Vec3(-1.0f, 0.0f, 2.0f)[axis];
    EXPECT_EQ(vertex.position[axis], face);
  }
  expectClosedSolid(box);
  expectUnitNormals(box);
}

// The square stands under the viewpoint, (3, 5, -7), whose foot on the plane
// y = 1 is (3, 1, -7), and reaches planeSize / 2 from it.
TEST(Tessellation, CentresAPlanesSquareUnderTheViewpoint) {
  const Plane plane(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 0);
  const Tessellation square = tessellate(plane);
  Vec3 low(kInfinity), high(-kInfinity);
  for (const SurfaceVertex& vertex : square.vertices) {
    low = glm::min(low, vertex.position);
    high = glm::max(high, vertex.position);
    EXPECT_EQ(vertex.normal, Vec3(0.0f, 1.0f, 0.0f));
    // The plane's texture coordinates: u = x, v = -z from the plane's point.
    EXPECT_NEAR(vertex.uv.x, vertex.position.x, 1e-3f);
    EXPECT_NEAR(vertex.uv.y, -vertex.position.z, 1e-3f);
  }
  const float half = 0.5f * kDefaultPlaneSize;
  EXPECT_NEAR(low.x, 3.0f - half, 1e-6f * half);
  EXPECT_NEAR(high.z, -7.0f + half, 1e-6f * half);
  EXPECT_EQ(low.y, 1.0f);
  EXPECT_EQ(high.y, 1.0f);
  EXPECT_FALSE(square.enclosesSolid);
  expectWoundAroundItsNormals(square);
  expectUnitNormals(square);
}

TEST(Tessellation, FansAConvexPolygon) {
  const std::vector<Vec3> corners = {Vec3(0.0f), Vec3(2.0f, 0.0f, 0.0f), Vec3(3.0f, 1.0f, 0.0f),
                                     Vec3(1.0f, 2.0f, 0.0f), Vec3(-1.0f, 1.0f, 0.0f)};
  const Tessellation polygon = tessellate(ConvexPolygon(corners, 0));
  EXPECT_EQ(polygon.triangles.size(), 3u);
  EXPECT_FALSE(polygon.enclosesSolid);
  expectWoundAroundItsNormals(polygon);
  expectUnitNormals(polygon);
}

TEST(Tessellation, KnowsWhichMeshesCloseAroundASolid) {
  const std::vector<Vec3> corners = {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f),
                                     Vec3(0.0f, 0.0f, 1.0f)};
  const std::vector<std::array<int, 3>> tetrahedron = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_TRUE(tessellate(TriangleMesh(corners, tetrahedron, 0)).enclosesSolid);
  std::vector<std::array<int, 3>> open(tetrahedron.begin(), tetrahedron.end() - 1);
  EXPECT_FALSE(tessellate(TriangleMesh(corners, open, 0)).enclosesSolid);
  std::vector<std::array<int, 3>> inconsistent = tetrahedron;
  std::swap(inconsistent[3][0], inconsistent[3][1]);
  EXPECT_FALSE(tessellate(TriangleMesh(corners, inconsistent, 0)).enclosesSolid);
  expectWoundAroundItsNormals(tessellate(TriangleMesh(corners, tetrahedron, 0)));
  expectUnitNormals(tessellate(TriangleMesh(corners, tetrahedron, 0)));
}

// Two cones base to base (a bipyramid) of `slices` sides: a closed solid in
// which each apex has `slices` edges.
std::pair<std::vector<Vec3>, std::vector<std::array<int, 3>>> bipyramid(int slices) {
  std::vector<Vec3> corners = {Vec3(0.0f, 0.0f, 1.0f), Vec3(0.0f, 0.0f, -1.0f)};
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < slices; ++i) {
    const float angle = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
    corners.emplace_back(std::cos(angle), std::sin(angle), 0.0f);
    const int here = 2 + i;
    const int next = 2 + (i + 1) % slices;
    triangles.push_back({0, here, next});
    triangles.push_back({1, next, here});
  }
  return {corners, triangles};
}

TEST(Tessellation, KnowsASolidWhoseVerticesHaveThousandsOfEdges) {
  auto [corners, triangles] = bipyramid(5000);
  EXPECT_TRUE(enclosesSolid(corners, triangles));
  std::swap(triangles[7000][1], triangles[7000][2]);
  EXPECT_FALSE(enclosesSolid(corners, triangles)) << "one triangle turned the other way";
  std::swap(triangles[7000][1], triangles[7000][2]);
  triangles.push_back(triangles[123]);
  EXPECT_FALSE(enclosesSolid(corners, triangles)) << "one triangle twice";
}

// A grid of squares over the unit square, each cut in two, bent, with normals
// and texture coordinates at its vertices or not.
MeshGeometry grid(int side, bool withAttributes) {
  MeshGeometry geometry =
      shape_testing::squareGrid(side, [](Vec2 at) { return Vec3(at.y, at.x, at.x * at.y); });
  if (!withAttributes) return geometry;
  for (const Vec3& position : geometry.positions) {
    geometry.normals.push_back(glm::normalize(Vec3(-position.y, -position.x, 1.0f)));
    geometry.uvs.push_back(Vec2(position));
  }
  return geometry;
}

// With normals at its vertices, a mesh is tessellated as it is: its
// vertices, its triangles, each on its own primitive.
TEST(Tessellation, TakesAMeshWithNormalsAsItIs) {
  const MeshGeometry geometry = grid(40, true);
  const Tessellation tessellation = tessellate(TriangleMesh(geometry, 0));
  ASSERT_EQ(tessellation.vertices.size(), geometry.positions.size());
  for (std::size_t i = 0; i < geometry.positions.size(); ++i) {
    EXPECT_EQ(tessellation.vertices[i].position, geometry.positions[i]);
    EXPECT_EQ(tessellation.vertices[i].normal, geometry.normals[i]);
    EXPECT_EQ(tessellation.vertices[i].uv, geometry.uvs[i]);
  }
  EXPECT_EQ(tessellation.triangles, geometry.triangles);
  for (int triangle = 0; triangle < static_cast<int>(tessellation.primitives.size()); ++triangle)
    ASSERT_EQ(tessellation.primitives[triangle], triangle);
}

// Without, each triangle has three corners of its own, with its flat normal.
TEST(Tessellation, GivesEachTriangleOfAMeshWithoutNormalsCornersOfItsOwn) {
  const MeshGeometry geometry = grid(40, false);
  const Tessellation tessellation = tessellate(TriangleMesh(geometry, 0));
  ASSERT_EQ(tessellation.triangles.size(), geometry.triangles.size());
  ASSERT_EQ(tessellation.vertices.size(), 3 * geometry.triangles.size());
  for (int triangle = 0; triangle < static_cast<int>(geometry.triangles.size()); ++triangle) {
    const auto& [a, b, c] = geometry.triangles[triangle];
    const Vec3 flat =
        windingNormal(geometry.positions[a], geometry.positions[b], geometry.positions[c]);
    EXPECT_EQ(tessellation.triangles[triangle],
              (std::array<int, 3>{3 * triangle, 3 * triangle + 1, 3 * triangle + 2}));
    EXPECT_EQ(tessellation.primitives[triangle], triangle);
    for (int corner = 0; corner < 3; ++corner) {
      const SurfaceVertex& vertex = tessellation.vertices[3 * triangle + corner];
      EXPECT_EQ(vertex.position, geometry.positions[geometry.triangles[triangle][corner]]);
      EXPECT_EQ(vertex.normal, flat);
    }
  }
}

// A triangle with a corner twice covers nothing: it is left out, and the
// others keep their primitives.
TEST(Tessellation, LeavesOutAMeshTriangleWithARepeatedCorner) {
  MeshGeometry geometry;
  geometry.positions = {Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f),
                        Vec3(1.0f, 1.0f, 0.0f)};
  geometry.normals.assign(4, Vec3(0.0f, 0.0f, 1.0f));
  geometry.triangles = {{0, 1, 2}, {1, 1, 2}, {1, 3, 2}};
  const Tessellation tessellation = tessellate(TriangleMesh(std::move(geometry), 0));
  EXPECT_EQ(tessellation.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 2}}));
  EXPECT_EQ(tessellation.primitives, (std::vector<int>{0, 2}));
}

// Placed by a transform that stretches it, a cone keeps its normals'
// lengths, their weights, while their directions turn.
TEST(Tessellation, KeepsTheWeightsOfAConesNormalsThroughATransform) {
  const Cone cone(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 1.0f, 2.0f, 0);
  TransformSpec stretch;
  stretch.scale = Vec3(3.0f, 1.0f, 0.5f);
  const Tessellation alone = tessellate(cone);
  const Tessellation placed =
      tessellate(TransformedShape(std::make_unique<Cone>(cone), worldFromObject(stretch)));
  ASSERT_EQ(alone.vertices.size(), placed.vertices.size());
  for (std::size_t i = 0; i < alone.vertices.size(); ++i)
    EXPECT_NEAR(glm::length(placed.vertices[i].normal), glm::length(alone.vertices[i].normal),
                1e-5f);
}

// A mirroring transform turns the winding around; the tessellation turns it
// back, so that it still winds around the (outward) normals.
TEST(Tessellation, KeepsTheWindingThroughAMirroringTransform) {
  TransformSpec mirror;
  mirror.scale = Vec3(-1.0f, 2.0f, 1.0f);
  mirror.translate = Vec3(0.0f, 3.0f, 0.0f);
  const TransformedShape shape(std::make_unique<Sphere>(Vec3(1.0f, 0.0f, 0.0f), 1.0f, 0),
                               worldFromObject(mirror));
  const Tessellation placed = tessellate(shape);
  // The centre moved to (-1, 3, 0); the normals point away from it.
  for (const SurfaceVertex& vertex : placed.vertices)
    EXPECT_GT(glm::dot(vertex.normal, vertex.position - Vec3(-1.0f, 3.0f, 0.0f)), 0.0f);
  expectClosedSolid(placed);
  expectUnitNormals(placed);
}

}  // namespace
}  // namespace rise
