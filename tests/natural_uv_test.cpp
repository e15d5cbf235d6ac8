// The natural texture coordinates of every primitive, in the ray tracer and
// in the tessellations that the visible-surface algorithms draw, and the
// tangents dP/du and dP/dv that bump maps tilt the normal along.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::expectTangentsMatchTheMapping;
using shape_testing::expectUv;
using shape_testing::intersect;
using shape_testing::uvSeenAlong;

constexpr float kTolerance = 1e-4f;

// The distance between two u coordinates on a surface that wraps at u = 1.
float wrappedDistance(float a, float b) {
  const float d = std::abs(a - b);
  return std::min(d, 1.0f - d);
}

TEST(NaturalUv, SphereIsLongitudeAndLatitude) {
  const Sphere sphere(Vec3(0.0f), 2.0f, 0);
  // Seen from -z the facing point is at u = 1/4; u grows towards -x, to the
  // viewer's right; v is 0 at the south pole and 1 at the north.
  expectUv(uvSeenAlong(sphere, Vec3(0, 0, -5), Vec3(0, 0, 1)), {0.25f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(5, 0, 0), Vec3(-1, 0, 0)), {0.0f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(0, 0, 5), Vec3(0, 0, -1)), {0.75f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(-5, 0, 0), Vec3(1, 0, 0)), {0.5f, 0.5f});
  EXPECT_NEAR(uvSeenAlong(sphere, Vec3(0, 5, 0), Vec3(0, -1, 0)).y, 1.0f, kTolerance);
  EXPECT_NEAR(uvSeenAlong(sphere, Vec3(0, -5, 0), Vec3(0, 1, 0)).y, 0.0f, kTolerance);
  // 45 degrees north of the point facing -z: v = 3/4.
  const Vec3 north45 = Vec3(0.0f, std::sqrt(2.0f), -std::sqrt(2.0f));
  expectUv(uvSeenAlong(sphere, 3.0f * north45, -north45), {0.25f, 0.75f});
}

TEST(NaturalUv, BoxMapsEachFaceOntoTheUnitSquareSeenFromOutside) {
  const Box box(Vec3(0.0f), Vec3(2.0f, 1.0f, 4.0f), 0);
  // The -z face, seen from -z: u grows to the right (-x), v up.
  expectUv(uvSeenAlong(box, Vec3(0.5f, 0.75f, -5), Vec3(0, 0, 1)), {0.75f, 0.75f});
  // The +z face, seen from +z: right is +x.
  expectUv(uvSeenAlong(box, Vec3(0.5f, 0.75f, 9), Vec3(0, 0, -1)), {0.25f, 0.75f});
  // The +x face, seen from +x: right is -z.
  expectUv(uvSeenAlong(box, Vec3(7, 0.25f, 1), Vec3(-1, 0, 0)), {0.75f, 0.25f});
  // The top: u along x, v along -z.
  expectUv(uvSeenAlong(box, Vec3(1.5f, 3, 1), Vec3(0, -1, 0)), {0.75f, 0.75f});
  // The bottom: u along x, v along +z.
  expectUv(uvSeenAlong(box, Vec3(1.5f, -3, 1), Vec3(0, 1, 0)), {0.75f, 0.25f});
}

TEST(NaturalUv, CylinderSideGoesAroundAndAlongTheAxisAndCapsArePlanar) {
  const Cylinder cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 4.0f, 0);
  expectUv(uvSeenAlong(cylinder, Vec3(0, 1, -5), Vec3(0, 0, 1)), {0.25f, 0.25f});
  expectUv(uvSeenAlong(cylinder, Vec3(-5, 3, 0), Vec3(1, 0, 0)), {0.5f, 0.75f});
  expectUv(uvSeenAlong(cylinder, Vec3(0, 9, 0), Vec3(0, -1, 0)), {0.5f, 0.5f});
  expectUv(uvSeenAlong(cylinder, Vec3(0, -9, 0), Vec3(0, 1, 0)), {0.5f, 0.5f});
  const Vec2 rim = uvSeenAlong(cylinder, Vec3(0.999f, 9, 0), Vec3(0, -1, 0));
  EXPECT_NEAR(glm::length(rim - Vec2(0.5f)), 0.4995f, kTolerance);
}

TEST(NaturalUv, ConeSideRunsFromBaseToApex) {
  const Cone cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0);
  // Halfway up, the side is 0.5 from the axis.
  expectUv(uvSeenAlong(cone, Vec3(0, 1, -5), Vec3(0, 0, 1)), {0.25f, 0.5f});
  expectUv(uvSeenAlong(cone, Vec3(0, -9, 0), Vec3(0, 1, 0)), {0.5f, 0.5f});
}

TEST(NaturalUv, TriangleIsBarycentric) {
  const Triangle triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 0)}, 0);
  expectUv(uvSeenAlong(triangle, Vec3(1, 0.5f, -3), Vec3(0, 0, 1)), {0.25f, 0.25f});
}

TEST(NaturalUv, PolygonMapsItsBoundingRectangleOntoTheUnitSquare) {
  const ConvexPolygon quad({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0);
  expectUv(uvSeenAlong(quad, Vec3(1, 1.5f, -3), Vec3(0, 0, 1)), {0.25f, 0.75f});
}

Tessellation tessellationOf(const Shape& shape, int level = 4) {
  Tessellation out;
  TessellationSettings settings;
  settings.level = level;
  shape.tessellate(settings, out);
  return out;
}

// Each vertex of the tessellation has the coordinates the ray tracer finds
// there (up to the seam, where 0 and 1 meet), and no triangle's u spans
// more than a few segments: a triangle across the seam would smear the whole
// texture backwards over it.
void expectTessellationAgreesWithRayTracing(const Shape& shape, float largestUSpan,
                                            bool uSingularAtVEnds = false) {
  const Tessellation tessellation = tessellationOf(shape);
  std::size_t checked = 0;
  for (const SurfaceVertex& vertex : tessellation.vertices) {
    // Straight in towards the vertex, from outside, along its normal; a ray
    // that grazes an edge may miss, or find the face across the edge.
    const Vec3 normal = normalizedOrZero(vertex.normal);
    const auto result = intersect(shape, Ray{vertex.position + 0.5f * normal, -normal});
    if (!result.found || glm::dot(result.surface.normal, normal) < 0.999f) continue;
    ++checked;
    // At the poles and the apex u is not defined.
    const bool atSingularEnd = uSingularAtVEnds && (vertex.uv.y > 0.9999f || vertex.uv.y < 1e-4f);
    if (!atSingularEnd) {
      EXPECT_LT(wrappedDistance(result.surface.uv.x, vertex.uv.x), 1e-3f);
    }
    EXPECT_NEAR(result.surface.uv.y, vertex.uv.y, 1e-3f);
  }
  EXPECT_GT(checked, tessellation.vertices.size() / 4);
  for (const auto& triangle : tessellation.triangles) {
    float low = 1.0f, high = 0.0f;
    for (int corner : triangle) {
      low = std::min(low, tessellation.vertices[corner].uv.x);
      high = std::max(high, tessellation.vertices[corner].uv.x);
    }
    EXPECT_LE(high - low, largestUSpan);
  }
}

TEST(NaturalUv, SphereTessellationHasTheRayTracersCoordinatesAndNoSeamGap) {
  expectTessellationAgreesWithRayTracing(Sphere(Vec3(1, 2, 3), 2.0f, 0), 1.01f / 16.0f, true);
}

TEST(NaturalUv, CylinderTessellationHasTheRayTracersCoordinatesAndNoSeamGap) {
  expectTessellationAgreesWithRayTracing(Cylinder(Vec3(0.0f), Vec3(1, 1, 0), 1.0f, 2.0f, 0), 1.0f);
}

TEST(NaturalUv, ConeTessellationHasTheRayTracersCoordinates) {
  expectTessellationAgreesWithRayTracing(Cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0), 1.0f,
                                         true);
}

TEST(NaturalUv, FlatShapesTessellateWithTheRayTracersCoordinates) {
  expectTessellationAgreesWithRayTracing(Box(Vec3(-1.0f), Vec3(2.0f, 1.0f, 3.0f), 0), 1.0f);
  expectTessellationAgreesWithRayTracing(Triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 1)}, 0),
                                         1.0f);
  expectTessellationAgreesWithRayTracing(
      ConvexPolygon({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0), 1.0f);
}

TEST(NaturalUv, CurvedSideTrianglesSpanOneSegmentOfU) {
  // 16 segments around at level 4: every side triangle spans 1/16 of u.
  const Tessellation cylinder = tessellationOf(Cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 1.0f, 0));
  for (const auto& triangle : cylinder.triangles) {
    const SurfaceVertex& a = cylinder.vertices[triangle[0]];
    if (glm::dot(a.normal, Vec3(0, 1, 0)) != 0.0f) continue;  // a cap
    float low = 1.0f, high = 0.0f;
    for (int corner : triangle) {
      low = std::min(low, cylinder.vertices[corner].uv.x);
      high = std::max(high, cylinder.vertices[corner].uv.x);
    }
    EXPECT_NEAR(high - low, 1.0f / 16.0f, 1e-5f);
  }
}

TEST(NaturalUv, TangentsAreTheDerivativesOfTheMapping) {
  expectTangentsMatchTheMapping(Sphere(Vec3(0.0f), 2.0f, 0), Vec3(1, 0.5f, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Box(Vec3(0.0f), Vec3(2, 1, 4), 0), Vec3(0.5f, 0.6f, -5),
                                Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Box(Vec3(0.0f), Vec3(2, 1, 4), 0), Vec3(1.5f, 3, 1),
                                Vec3(0, -1, 0));
  const Cylinder cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 4.0f, 0);
  expectTangentsMatchTheMapping(cylinder, Vec3(0.3f, 1, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(cylinder, Vec3(0.3f, 9, 0.2f), Vec3(0, -1, 0));
  expectTangentsMatchTheMapping(Cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0),
                                Vec3(0.2f, 0.7f, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 1)}, 0),
                                Vec3(1, 0.5f, -3), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(
      ConvexPolygon({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0),
      Vec3(1, 0.5f, -3), Vec3(0, 0, 1));
}

}  // namespace
}  // namespace rise
