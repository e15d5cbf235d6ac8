#pragma once

#include <vector>

#include "scene/shape.hpp"

namespace rise {

// A planar convex polygon of three or more vertices, in order around it; its
// normal follows their counter-clockwise winding. Use isPlanarConvexPolygon to
// check the vertices first.
bool isPlanarConvexPolygon(const std::vector<Vec3>& vertices);

// Intersected as its plane, then kept if the point is on the inner side of
// every edge; the edges belong to the polygon. Its texture coordinates are a
// planar mapping, u along the first edge and v across it, scaled so that the
// rectangle around the polygon is the unit square.
class ConvexPolygon final : public Shape {
 public:
  ConvexPolygon(std::vector<Vec3> vertices, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  bool tessellationIsExact() const override { return true; }

 private:
  std::vector<Vec3> vertices_;
  Vec3 normal_;
  // For the edge from vertex i to vertex i + 1: the normal in the polygon's
  // plane pointing into the polygon.
  std::vector<Vec3> edgeInwardNormals_;
  Vec3 uAxis_;
  Vec3 vAxis_;
  Vec2 uvLowest_;  // the mapped corner of the rectangle around the polygon
  Vec2 uvSize_;

  Vec2 textureCoordinates(const Vec3& position) const;
};

}  // namespace rise
