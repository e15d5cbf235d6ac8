#include "scene/light.hpp"

#include <cmath>

#include "core/warps.hpp"

namespace rise {

DiskLight::DiskLight(Vec3 center, Vec3 normal, float radius, Color color)
    : Light(color), center_(center) {
  orthonormalBasis(glm::normalize(normal), axisU_, axisV_);
  axisU_ *= radius;
  axisV_ *= radius;
}

LightSample DiskLight::illuminate(const Vec3& point, const Vec2& u) const {
  const Vec2 disk = squareToDisk(u);
  return towards(point, center_ + disk.x * axisU_ + disk.y * axisV_);
}

LightSample SphereLight::illuminate(const Vec3& point, const Vec2& u) const {
  const Vec3 toCentre = center_ - point;
  const float distance = glm::length(toCentre);
  if (distance <= radius_) return towards(point, center_);  // inside the light
  Vec3 across, up;
  orthonormalBasis(toCentre / distance, across, up);
  const Vec2 disk = radius_ * squareToDisk(u);
  return towards(point, center_ + disk.x * across + disk.y * up);
}

}  // namespace rise
