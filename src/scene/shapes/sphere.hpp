#pragma once

#include "scene/shape.hpp"
#include "scene/shapes/quadratic.hpp"

namespace rise {

// Where the ray first meets the sphere of that centre and squared radius at
// t in (tMin, tMax), leaving the sphere or entering it. Inline, because it is
// the inner loop of a scene of spheres.
inline bool intersectSphere(const Ray& ray, const Vec3& center, float radiusSquared, float tMin,
                            float tMax, float& t) {
  const Vec3 fromCenter = ray.origin - center;
  // Most rays start outside a sphere and go away from it, or miss it wide:
  // tell them apart before solving anything.
  const float halfB = glm::dot(fromCenter, ray.direction);
  if (halfB > 0.0f && glm::dot(fromCenter, fromCenter) > radiusSquared) return false;
  float roots[2];
  if (!solveLineAtDistance(fromCenter, ray.direction, radiusSquared, roots[0], roots[1]))
    return false;
  for (float root : roots) {
    if (root > tMin && root < tMax) {
      t = root;
      return true;
    }
  }
  return false;
}

// A sphere: the points at distance radius from center. A ray tangent to it
// touches it at one point, which counts as a hit.
class Sphere final : public Shape {
 public:
  Sphere(Vec3 center, float radius, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  SurfacePoint pointAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  bool primitiveSphere(int primitive, Vec3& center, float& radiusSquared) const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;

 private:
  Vec3 center_;
  float radius_;
  float radiusSquared_;
};

}  // namespace rise
