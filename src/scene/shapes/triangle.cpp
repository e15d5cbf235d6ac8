#include "scene/shapes/triangle.hpp"

namespace rise {

Triangle::Triangle(const std::array<Vec3, 3>& vertices, int material)
    : Shape(material),
      vertices_(vertices),
      normal_(windingNormal(vertices[0], vertices[1], vertices[2])) {}

bool Triangle::intersect(const Ray& ray, float tMin, Hit& hit,
                         IntersectionCounters& counters) const {
  ++counters.tests;
  if (!intersectTriangle(ray, vertices_[0], vertices_[1], vertices_[2], tMin, hit.t, hit.t,
                         hit.barycentric))
    return false;
  hit.shape = this;
  return true;
}

SurfacePoint Triangle::surfaceAt(const Ray& ray, const Hit& hit) const {
  // Texture coordinates are the barycentric ones: (0, 0), (1, 0) and (0, 1)
  // at the three corners.
  SurfacePoint surface(ray.at(hit.t), normal_, hit.barycentric);
  surface.dpdu = vertices_[1] - vertices_[0];
  surface.dpdv = vertices_[2] - vertices_[0];
  return surface;
}

Bounds3 Triangle::bounds() const {
  Bounds3 box;
  for (const Vec3& vertex : vertices_) box.grow(vertex);
  return box;
}

bool Triangle::primitiveTriangle(int /*primitive*/, std::array<Vec3, 3>& corners) const {
  corners = vertices_;
  return true;
}

void Triangle::tessellate(const TessellationSettings&, Tessellation& out) const {
  const std::array<Vec2, 3> cornerUvs{Vec2(0.0f, 0.0f), Vec2(1.0f, 0.0f), Vec2(0.0f, 1.0f)};
  for (int corner = 0; corner < 3; ++corner)
    out.addVertex({vertices_[corner], normal_, cornerUvs[corner]});
  out.addTriangle(0, 1, 2);
}

}  // namespace rise
