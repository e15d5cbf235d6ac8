#include "scene/shapes/transformed_shape.hpp"

#include <utility>

namespace rise {

TransformedShape::TransformedShape(std::unique_ptr<Shape> shape, const Mat4& worldFromObject)
    : Shape(shape->material()), shape_(std::move(shape)), placement_(worldFromObject) {}

bool TransformedShape::intersect(const Ray& ray, float tMin, Hit& hit,
                                 IntersectionCounters& counters) const {
  if (!shape_->intersect(placement_.toObject(ray), tMin, hit, counters)) return false;
  // The hit comes back here, so that surfaceAt can bring it to the world.
  hit.shape = this;
  return true;
}

SurfacePoint TransformedShape::surfaceAt(const Ray& ray, const Hit& hit) const {
  return placement_.toWorld(shape_->surfaceAt(placement_.toObject(ray), hit));
}

SurfacePoint TransformedShape::pointAt(const Ray& ray, const Hit& hit) const {
  return placement_.toWorld(shape_->pointAt(placement_.toObject(ray), hit));
}

Bounds3 TransformedShape::bounds() const { return placement_.boundsToWorld(shape_->bounds()); }

int TransformedShape::primitiveCount() const { return shape_->primitiveCount(); }

Bounds3 TransformedShape::primitiveBounds(int primitive) const {
  return placement_.boundsToWorld(shape_->primitiveBounds(primitive));
}

bool TransformedShape::intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                                          IntersectionCounters& counters) const {
  if (!shape_->intersectPrimitive(primitive, placement_.toObject(ray), tMin, hit, counters))
    return false;
  hit.shape = this;
  return true;
}

void TransformedShape::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  tessellatePlaced(*shape_, placement_.worldFromObject(), settings, out);
}

std::uint64_t TransformedShape::tessellatedTriangles(int level) const {
  return shape_->tessellatedTriangles(level);
}

}  // namespace rise
