#pragma once

#include "scene/shape.hpp"

namespace rise {

// An axis-aligned box between two opposite corners (a transform can turn it),
// intersected by the slab method (Kay and Kajiya, "Ray Tracing Complex Scenes",
// SIGGRAPH 1986): the ray is inside the box where it is inside all three pairs
// of parallel face planes. Faces, edges and corners belong to the box, so a ray
// lying in a face's plane touches it and hits the face it enters by.
class Box final : public Shape {
 public:
  Box(Vec3 min, Vec3 max, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  bool tessellationIsExact() const override { return true; }

 private:
  Vec3 min_;
  Vec3 max_;
};

}  // namespace rise
