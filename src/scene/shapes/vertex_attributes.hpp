// Values given at a triangle's corners (normals, texture coordinates),
// interpolated across it with the barycentric coordinates of a hit.
#pragma once

#include <array>

#include "core/math.hpp"
#include "scene/shape.hpp"

namespace rise {

// The value at the point (1 - u - v) v0 + u v1 + v v2 of the triangle whose
// corners hold a0, a1 and a2, for barycentric = (u, v).
template <typename T>
T atBarycentric(const T& a0, const T& a1, const T& a2, const Vec2& barycentric) {
  return (1.0f - barycentric.x - barycentric.y) * a0 + barycentric.x * a1 + barycentric.y * a2;
}

// Phong's normal interpolation ("Illumination for Computer Generated
// Pictures", CACM 18(6), 1975): the corners' normals blended and made unit
// again, so that the shading varies smoothly across the facets of a curved
// model. Where the blend vanishes or turns to the other side of the triangle
// (corner normals that disagree with its winding), the flat normal stands in.
inline Vec3 interpolatedNormal(const Vec3& geometricNormal, const Vec3& n0, const Vec3& n1,
                               const Vec3& n2, const Vec2& barycentric) {
  const Vec3 blend = atBarycentric(n0, n1, n2, barycentric);
  const float length = glm::length(blend);
  if (!(length > 1e-6f) || glm::dot(blend, geometricNormal) <= 0.0f) return geometricNormal;
  return blend / length;
}

// What Phong's interpolation worked from at the point of barycentric
// coordinates (u, v) of a triangle (shape.hpp).
inline NormalInterpolation normalInterpolation(const std::array<Vec3, 3>& corners,
                                               const std::array<Vec3, 3>& normals,
                                               const Vec2& barycentric) {
  return {corners, normals,
          Vec3(1.0f - barycentric.x - barycentric.y, barycentric.x, barycentric.y)};
}

}  // namespace rise
