// What the shape tests share: one ray against one shape, asked as a renderer
// asks it, and the answer compared with analytic values.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "core/color.hpp"
#include "scene/mesh_geometry.hpp"
#include "scene/shape.hpp"
#include "scene/tessellation.hpp"

namespace rise::shape_testing {

struct Intersection {
  bool found = false;
  Hit hit;
  SurfacePoint surface{};
  IntersectionCounters counters;
};

// Intersects over (tMin, tMax) and, on a hit, asks the shape for its surface.
inline Intersection intersect(const Shape& shape, const Ray& ray, float tMin = 0.0f,
                              float tMax = kInfinity) {
  Intersection result;
  result.hit.t = tMax;
  result.found = shape.intersect(ray, tMin, result.hit, result.counters);
  if (result.found) result.surface = shape.surfaceAt(ray, result.hit);
  return result;
}

// The texture coordinates where a ray from `origin` along `direction` meets
// the shape, which it must.
inline Vec2 uvSeenAlong(const Shape& shape, const Vec3& origin, const Vec3& direction) {
  const Intersection result = intersect(shape, Ray{origin, direction});
  EXPECT_TRUE(result.found);
  return result.surface.uv;
}

inline void expectUv(const Vec2& actual, const Vec2& expected, float tolerance = 1e-4f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

inline std::string text(const Vec3& v) {
  std::ostringstream out;
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

// Fails on NaN too.
inline ::testing::AssertionResult nearlyEqual(const Vec3& actual, const Vec3& expected,
                                              float tolerance = 1e-4f) {
  const Vec3 error = glm::abs(actual - expected);
  if (error.x <= tolerance && error.y <= tolerance && error.z <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << text(actual) << " is not within " << tolerance << " of " << text(expected);
}

inline void expectColor(const Color& actual, const Color& expected, float tolerance = 1e-4f) {
  EXPECT_TRUE(nearlyEqual(actual, expected, tolerance));
}

// A hit at t, with the given point and unit normal.
inline ::testing::AssertionResult hitsAt(const Intersection& result, float t, const Vec3& position,
                                         const Vec3& normal, float tolerance = 1e-4f) {
  if (!result.found) return ::testing::AssertionFailure() << "no hit";
  if (!(std::abs(result.hit.t - t) <= tolerance))
    return ::testing::AssertionFailure() << "t = " << result.hit.t << ", expected " << t;
  if (auto near = nearlyEqual(result.surface.position, position, tolerance); !near)
    return ::testing::AssertionFailure() << "position " << near.message();
  if (auto near = nearlyEqual(result.surface.normal, normal, tolerance); !near)
    return ::testing::AssertionFailure() << "normal " << near.message();
  return ::testing::AssertionSuccess();
}

// A miss leaves the hit as it was.
inline ::testing::AssertionResult misses(const Intersection& result, float tMax = kInfinity) {
  if (result.found) return ::testing::AssertionFailure() << "hit at t = " << result.hit.t;
  if (result.hit.t != tMax || result.hit.shape != nullptr)
    return ::testing::AssertionFailure() << "a miss changed the hit";
  return ::testing::AssertionSuccess();
}

// The frame of an axis tilted 45 degrees from y towards x: it takes y to
// (1, 1, 0) / sqrt(2), x to (1, -1, 0) / sqrt(2) and keeps z, so that a case
// built around the y axis can be replayed around the tilted one.
inline Vec3 tilted(const Vec3& v) {
  const float s = std::sqrt(0.5f);
  return v.x * Vec3(s, -s, 0.0f) + v.y * Vec3(s, s, 0.0f) + Vec3(0.0f, 0.0f, v.z);
}

// How far the texture's u runs across one triangle of a tessellation: a
// triangle that smears the texture across a seam spans nearly all of it.
inline float uSpan(const Tessellation& tessellation, const std::array<int, 3>& triangle) {
  float low = kInfinity, high = -kInfinity;
  for (int corner : triangle) {
    low = std::min(low, tessellation.vertices[corner].uv.x);
    high = std::max(high, tessellation.vertices[corner].uv.x);
  }
  return high - low;
}

// side x side squares, each cut in two along a diagonal: vertex (i, j),
// numbered i (side + 1) + j, at place((i, j) / side).
inline MeshGeometry squareGrid(int side, const std::function<Vec3(Vec2)>& place) {
  MeshGeometry geometry;
  const auto at = [&](int i, int j) { return i * (side + 1) + j; };
  for (int i = 0; i <= side; ++i)
    for (int j = 0; j <= side; ++j)
      geometry.positions.push_back(place(Vec2(i, j) / static_cast<float>(side)));
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      geometry.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      geometry.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  return geometry;
}

// dP/du and dP/dv are the rates of change of the position with the mapping's
// coordinates along the surface: a step along dP/du (back onto the surface)
// moves u alone.
inline void expectTangentsMatchTheMapping(const Shape& shape, const Vec3& origin,
                                          const Vec3& direction) {
  const auto at = intersect(shape, Ray{origin, direction});
  ASSERT_TRUE(at.found);
  const float step = 1e-3f;
  for (int axis = 0; axis < 2; ++axis) {
    const Vec3 tangent = axis == 0 ? at.surface.dpdu : at.surface.dpdv;
    const auto there = intersect(
        shape,
        Ray{at.surface.position + step * tangent + 0.1f * at.surface.normal, -at.surface.normal});
    ASSERT_TRUE(there.found);
    const Vec2 change = (there.surface.uv - at.surface.uv) / step;
    EXPECT_NEAR(change[axis], 1.0f, 2e-2f) << "axis " << axis;
    EXPECT_NEAR(change[1 - axis], 0.0f, 2e-2f) << "axis " << axis;
  }
}

}  // namespace rise::shape_testing
