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
  return {Vec3(worldFromObject_ * glm::vec4(object.position, 1.0f)),
          glm::normalize(normalToWorld_ * object.normal)};
}

}  // namespace rise
