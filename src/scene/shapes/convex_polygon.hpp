#pragma once

#include <vector>

#include "scene/shape.hpp"

namespace rise {

// A planar convex polygon of three or more vertices, in order around it; its
// normal follows their counter-clockwise winding. Use isPlanarConvexPolygon to
// check the vertices first.
bool isPlanarConvexPolygon(const std::vector<Vec3>& vertices);

// Intersected as its plane, then kept if the point is on the inner side of
// every edge; the edges belong to the polygon.
class ConvexPolygon final : public Shape {
 public:
  ConvexPolygon(std::vector<Vec3> vertices, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;

 private:
  std::vector<Vec3> vertices_;
  Vec3 normal_;
  // For the edge from vertex i to vertex i + 1: the normal in the polygon's
  // plane pointing into the polygon.
  std::vector<Vec3> edgeInwardNormals_;
};

}  // namespace rise
