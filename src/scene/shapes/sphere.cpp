#include "scene/shapes/sphere.hpp"

#include "scene/shapes/quadratic.hpp"

namespace rise {

Sphere::Sphere(Vec3 center, float radius, int material)
    : Shape(material), center_(center), radius_(radius), radiusSquared_(radius * radius) {}

bool Sphere::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  const Vec3 fromCenter = ray.origin - center_;
  // Most rays start outside a sphere and go away from it, or miss it wide:
  // tell them apart before solving anything.
  const float halfB = glm::dot(fromCenter, ray.direction);
  if (halfB > 0.0f && glm::dot(fromCenter, fromCenter) > radiusSquared_) return false;
  float roots[2];
  if (!solveLineAtDistance(fromCenter, ray.direction, radiusSquared_, roots[0], roots[1]))
    return false;
  for (float t : roots) {
    if (t > tMin && t < hit.t) {
      hit.t = t;
      hit.shape = this;
      return true;
    }
  }
  return false;
}

SurfacePoint Sphere::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  return {position, (position - center_) / radius_};
}

}  // namespace rise
