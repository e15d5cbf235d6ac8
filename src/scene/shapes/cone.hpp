#pragma once

#include "scene/shape.hpp"

namespace rise {

// A solid circular cone, capped by its base disk of the given radius; its apex
// lies at base + height * axis (axis normalised). The side is the quadric
// |w|^2 = (1 + (radius / height)^2) (w . axis)^2 of the points w from the apex,
// cut to the nappe between apex and base.
class Cone final : public Shape {
 public:
  Cone(Vec3 base, Vec3 axis, float radius, float height, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;

 private:
  Vec3 base_;
  Vec3 axis_;
  float radius_;
  float height_;
  Vec3 apex_;
  float slopeFactor_;  // 1 + (radius / height)^2
};

}  // namespace rise
