#pragma once

#include "scene/shape.hpp"

namespace rise {

// A solid circular cylinder, capped at both ends: its axis runs from base
// along axis (any length; it is normalised) for height. The side is the
// infinite cylinder around the axis cut to that height; the caps are disks.
class Cylinder final : public Shape {
 public:
  Cylinder(Vec3 base, Vec3 axis, float radius, float height, int material);

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
  Vec3 top_;
};

}  // namespace rise
