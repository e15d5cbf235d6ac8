#include "scene/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rise {

Mat4 worldFromObject(const TransformSpec& spec) {
  // Each call multiplies on the right, so the last one written acts first on
  // a point: the scale, then x, y and z rotations, then the translation.
  Mat4 m = glm::translate(Mat4(1.0f), spec.translate);
  m = glm::rotate(m, radians(spec.rotateDegrees.z), Vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, radians(spec.rotateDegrees.y), Vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, radians(spec.rotateDegrees.x), Vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, spec.scale);
}

TransformSpec interpolate(const TransformSpec& from, const TransformSpec& to, float time) {
  return {glm::mix(from.scale, to.scale, time),
          glm::mix(from.rotateDegrees, to.rotateDegrees, time),
          glm::mix(from.translate, to.translate, time)};
}

namespace {

// A point of a surface carried by a map: points by it, directions along
// the surface by its linear part, normals by `normalMap`.
SurfacePoint moved(SurfacePoint surface, const Mat4& pointMap, const Mat3& normalMap) {
  const auto point = [&](const Vec3& p) { return Vec3(pointMap * glm::vec4(p, 1.0f)); };
  surface.position = point(surface.position);
  surface.normal = glm::normalize(normalMap * surface.normal);
  surface.shadingNormal = glm::normalize(normalMap * surface.shadingNormal);
  surface.dpdu = Mat3(pointMap) * surface.dpdu;
  surface.dpdv = Mat3(pointMap) * surface.dpdv;
  if (surface.interpolation) {
    for (int corner = 0; corner < 3; ++corner) {
      surface.interpolation->corners[corner] = point(surface.interpolation->corners[corner]);
      surface.interpolation->normals[corner] =
          normalizedOrZero(normalMap * surface.interpolation->normals[corner]);
    }
  }
  return surface;
}

}  // namespace

AffineMap::AffineMap(const Mat4& worldFromObject)
    : worldFromObject_(worldFromObject),
      objectFromWorld_(glm::inverse(worldFromObject)),
      normalToWorld_(glm::transpose(Mat3(objectFromWorld_))) {}

Ray AffineMap::toObject(const Ray& worldRay) const {
  return Ray{Vec3(objectFromWorld_ * glm::vec4(worldRay.origin, 1.0f)),
             Mat3(objectFromWorld_) * worldRay.direction, worldRay.time};
}

SurfacePoint AffineMap::toWorld(const SurfacePoint& object) const {
  return moved(object, worldFromObject_, normalToWorld_);
}

// Normals go back by the transpose of the inverse's inverse transpose.
SurfacePoint AffineMap::toObject(const SurfacePoint& world) const {
  return moved(world, objectFromWorld_, glm::transpose(Mat3(worldFromObject_)));
}

Vec3 AffineMap::pointToWorld(const Vec3& point) const {
  return Vec3(worldFromObject_ * glm::vec4(point, 1.0f));
}

Bounds3 AffineMap::boundsToWorld(const Bounds3& objectBox) const {
  if (objectBox.isEmpty()) return objectBox;
  if (!objectBox.isFinite()) return Bounds3::infinite();
  Bounds3 box;
  for (int corner = 0; corner < 8; ++corner) box.grow(pointToWorld(objectBox.corner(corner)));
  return box;
}

}  // namespace rise
