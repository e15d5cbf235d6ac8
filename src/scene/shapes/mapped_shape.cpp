#include "scene/shapes/mapped_shape.hpp"

#include <utility>

namespace rise {

MappedShape::MappedShape(std::unique_ptr<Shape> shape, const Mapping& mapping)
    : Shape(shape->material()), shape_(std::move(shape)), mapping_(mapping, shape_->bounds()) {}

bool MappedShape::intersect(const Ray& ray, float tMin, Hit& hit,
                            IntersectionCounters& counters) const {
  if (!shape_->intersect(ray, tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

SurfacePoint MappedShape::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfacePoint surface = shape_->surfaceAt(ray, hit);
  mapping_.mapOnto(surface);
  return surface;
}

SurfacePoint MappedShape::pointAt(const Ray& ray, const Hit& hit) const {
  return shape_->pointAt(ray, hit);
}

Bounds3 MappedShape::bounds() const { return shape_->bounds(); }

int MappedShape::primitiveCount() const { return shape_->primitiveCount(); }

Bounds3 MappedShape::primitiveBounds(int primitive) const {
  return shape_->primitiveBounds(primitive);
}

bool MappedShape::intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                                     IntersectionCounters& counters) const {
  if (!shape_->intersectPrimitive(primitive, ray, tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

bool MappedShape::primitiveTriangle(int primitive, std::array<Vec3, 3>& corners) const {
  return shape_->primitiveTriangle(primitive, corners);
}

bool MappedShape::primitiveSphere(int primitive, Vec3& center, float& radiusSquared) const {
  return shape_->primitiveSphere(primitive, center, radiusSquared);
}

void MappedShape::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  shape_->tessellate(settings, out);
  for (SurfaceVertex& vertex : out.vertices)
    vertex.uv = mapping_.uvAt(vertex.position, normalizedOrZero(vertex.normal));
  out.projection = &mapping_;
}

std::uint64_t MappedShape::tessellatedTriangles(int level) const {
  return shape_->tessellatedTriangles(level);
}

}  // namespace rise
