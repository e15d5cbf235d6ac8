#pragma once

#include "scene/shape.hpp"

namespace rise {

// Where the ray meets the plane through point with the given normal (any
// length), if that is at t in (tMin, tMax). A ray parallel to the plane, even
// one lying in it, misses it.
bool intersectPlane(const Ray& ray, Vec3 point, Vec3 normal, float tMin, float tMax, float& t);

// An infinite plane through point, facing along normal. Its texture
// coordinates are distances from point along two axes in the plane: u along
// the world x axis projected onto the plane (the z axis when the plane faces
// along x), and v = normal x u; for the floor (normal +y) that is u = x,
// v = -z.
class Plane final : public Shape {
 public:
  Plane(Vec3 point, Vec3 normal, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;

 private:
  Vec2 textureCoordinates(const Vec3& position) const;

  Vec3 point_;
  Vec3 normal_;
  Vec3 uAxis_;
  Vec3 vAxis_;
};

}  // namespace rise
