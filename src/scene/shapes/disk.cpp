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

}  // namespace rise
