#pragma once

#include "scene/shape.hpp"

namespace rise {

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
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;

 private:
  Vec3 center_;
  float radius_;
  float radiusSquared_;
};

}  // namespace rise
