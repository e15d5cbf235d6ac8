#include "scene/shapes/transformed_shape.hpp"

#include <utility>

namespace rise {

TransformedShape::TransformedShape(std::unique_ptr<Shape> shape, const Mat4& worldFromObject)
    : Shape(shape->material()),
      shape_(std::move(shape)),
      worldFromObject_(worldFromObject),
      objectFromWorld_(glm::inverse(worldFromObject)),
      normalToWorld_(glm::transpose(Mat3(objectFromWorld_))) {}

Ray TransformedShape::objectRay(const Ray& worldRay) const {
  return Ray{Vec3(objectFromWorld_ * glm::vec4(worldRay.origin, 1.0f)),
             Mat3(objectFromWorld_) * worldRay.direction, worldRay.time};
}

bool TransformedShape::intersect(const Ray& ray, float tMin, Hit& hit,
                                 IntersectionCounters& counters) const {
  if (!shape_->intersect(objectRay(ray), tMin, hit, counters)) return false;
  // The hit comes back here, so that surfaceAt can bring it to the world.
  hit.shape = this;
  return true;
}

SurfacePoint TransformedShape::surfaceAt(const Ray& ray, const Hit& hit) const {
  const SurfacePoint object = shape_->surfaceAt(objectRay(ray), hit);
  SurfacePoint world(Vec3(worldFromObject_ * glm::vec4(object.position, 1.0f)),
                     glm::normalize(normalToWorld_ * object.normal), object.uv);
  world.shadingNormal = glm::normalize(normalToWorld_ * object.shadingNormal);
  return world;
}

Bounds3 TransformedShape::bounds() const { return toWorld(shape_->bounds()); }

int TransformedShape::primitiveCount() const { return shape_->primitiveCount(); }

Bounds3 TransformedShape::primitiveBounds(int primitive) const {
  return toWorld(shape_->primitiveBounds(primitive));
}

bool TransformedShape::intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                                          IntersectionCounters& counters) const {
  if (!shape_->intersectPrimitive(primitive, objectRay(ray), tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

// An affine map takes a box to a parallelepiped, which lies inside the box
// around its eight corners.
Bounds3 TransformedShape::toWorld(const Bounds3& objectBox) const {
  if (objectBox.isEmpty()) return objectBox;
  if (!objectBox.isFinite()) return Bounds3::infinite();
  Bounds3 box;
  for (int corner = 0; corner < 8; ++corner)
    box.grow(Vec3(worldFromObject_ * glm::vec4(objectBox.corner(corner), 1.0f)));
  return box;
}

void TransformedShape::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  tessellatePlaced(*shape_, worldFromObject_, settings, out);
}

}  // namespace rise
