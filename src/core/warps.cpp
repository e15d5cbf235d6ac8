#include "core/warps.hpp"

#include <algorithm>
#include <cmath>

namespace rise {
namespace {

// The direction at height z on the unit sphere, turned by the square's u.x.
Vec3 atHeight(float z, float turn) {
  const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float angle = 2.0f * kPi * turn;
  return {radius * std::cos(angle), radius * std::sin(angle), z};
}

}  // namespace

void orthonormalBasis(const Vec3& axis, Vec3& u, Vec3& v) {
  // Frisvad's construction as revised by Duff et al. (JCGT 2017): branchless
  // but for the sign, and exact for every unit axis.
  const float sign = std::copysign(1.0f, axis.z);
  const float a = -1.0f / (sign + axis.z);
  const float b = axis.x * axis.y * a;
  u = Vec3(1.0f + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
  v = Vec3(b, sign + axis.y * axis.y * a, -axis.y);
}

Vec3 fromLocal(const Vec3& local, const Vec3& axis) {
  Vec3 u, v;
  orthonormalBasis(axis, u, v);
  return local.x * u + local.y * v + local.z * axis;
}

Vec2 squareToDisk(const Vec2& u) {
  const Vec2 offset = 2.0f * u - Vec2(1.0f);
  if (offset == Vec2(0.0f)) return Vec2(0.0f);
  float radius, angle;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    radius = offset.x;
    angle = (kPi / 4.0f) * (offset.y / offset.x);
  } else {
    radius = offset.y;
    angle = (kPi / 2.0f) - (kPi / 4.0f) * (offset.x / offset.y);
  }
  return radius * Vec2(std::cos(angle), std::sin(angle));
}

// Archimedes: a sphere's area between two heights is proportional to their
// distance, so a uniform height and turn are uniform on the sphere.
Vec3 squareToUniformSphere(const Vec2& u) { return atHeight(1.0f - 2.0f * u.y, u.x); }

Vec3 squareToUniformHemisphere(const Vec2& u) { return atHeight(1.0f - u.y, u.x); }

Vec3 squareToCosineHemisphere(const Vec2& u) {
  const Vec2 disk = squareToDisk(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disk, disk)));
  return {disk.x, disk.y, z};
}

float cosineHemisphereDensity(const Vec3& direction) {
  return direction.z > 0.0f ? direction.z / kPi : 0.0f;
}

// The cone's cap is the sphere's zone above its cosine: uniform heights
// within it, by Archimedes again.
Vec3 squareToUniformCone(const Vec2& u, float cosineOfHalfAngle) {
  return atHeight(1.0f - u.y * (1.0f - cosineOfHalfAngle), u.x);
}

float uniformConeDensity(const Vec3& direction, float cosineOfHalfAngle) {
  return direction.z >= cosineOfHalfAngle ? 1.0f / (2.0f * kPi * (1.0f - cosineOfHalfAngle)) : 0.0f;
}

// The inverse of the lobe's distribution in cos(theta): u = cos^(n+1).
Vec3 squareToPhongLobe(const Vec2& u, float exponent) {
  return atHeight(std::pow(1.0f - u.y, 1.0f / (exponent + 1.0f)), u.x);
}

float phongLobeDensity(const Vec3& direction, float exponent) {
  if (direction.z <= 0.0f) return 0.0f;
  return (exponent + 1.0f) / (2.0f * kPi) * std::pow(direction.z, exponent);
}

}  // namespace rise
