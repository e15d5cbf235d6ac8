// Vector types for the whole renderer. RISE computes in single precision:
// scenes are a few units across, and every ray offset (kRayEpsilon) is chosen
// for that scale.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <limits>

namespace rise {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// How far a secondary ray starts from the surface it leaves, so that it does
// not find that surface again through rounding ("shadow acne").
inline constexpr float kRayEpsilon = 1e-4f;

inline float radians(float degrees) { return degrees * (kPi / 180.0f); }

// Whether no component is NaN or infinite.
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline float maxComponent(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }

// The unit vector along v; zero for zero, which has no direction, and for a
// vector that is not finite. A finite v of any length has one: v is first
// scaled by its largest component, so that its squared length neither
// overflows (a length of 1e20) nor underflows.
inline Vec3 normalizedOrZero(const Vec3& v) {
  // Below this length, the squared length loses precision or underflows.
  constexpr float kShortest = 1e-18f;
  const float length = glm::length(v);
  if (length > kShortest && length < kInfinity) return v / length;
  const float largest = maxComponent(glm::abs(v));
  if (!(largest > 0.0f) || !isFinite(v)) return Vec3(0.0f);
  const Vec3 scaled = v / largest;
  return scaled / glm::length(scaled);
}

// The corner after corner i of a polygon of `count` corners, the last
// followed by the first: by a comparison rather than a division, since it
// runs for every edge of every polygon drawn.
inline std::size_t nextCorner(std::size_t i, std::size_t count) {
  return i + 1 < count ? i + 1 : 0;
}

// The axis (0, 1 or 2) of the largest component, the first of equals.
inline int largestAxis(const Vec3& v) {
  return v.x >= v.y && v.x >= v.z ? 0 : (v.y >= v.z ? 1 : 2);
}

}  // namespace rise
