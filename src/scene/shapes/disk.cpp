#include "scene/shapes/disk.hpp"

#include "scene/shapes/plane.hpp"

namespace rise {

bool intersectDisk(const Ray& ray, Vec3 center, Vec3 normal, float radiusSquared, float tMin,
                   float tMax, float& t) {
  float tPlane;
  if (!intersectPlane(ray, center, normal, tMin, tMax, tPlane)) return false;
  const Vec3 fromCenter = ray.at(tPlane) - center;
  if (glm::dot(fromCenter, fromCenter) > radiusSquared) return false;
  t = tPlane;
  return true;
}

Bounds3 diskBounds(Vec3 center, Vec3 unitNormal, float radius) {
  const Vec3 reach = radius * glm::sqrt(glm::max(Vec3(0.0f), Vec3(1.0f) - unitNormal * unitNormal));
  return {center - reach, center + reach};
}

}  // namespace rise
