#include "scene/shapes/plane.hpp"

#include <cmath>

namespace rise {

bool intersectPlane(const Ray& ray, Vec3 point, Vec3 normal, float tMin, float tMax, float& t) {
  const float approach = glm::dot(normal, ray.direction);
  if (approach == 0.0f) return false;
  const float tPlane = glm::dot(normal, point - ray.origin) / approach;
  if (!(tPlane > tMin && tPlane < tMax)) return false;
  t = tPlane;
  return true;
}

namespace {

Vec3 textureUAxis(const Vec3& normal) {
  const Vec3 reference =
      std::abs(normal.x) > 0.9f ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(reference - glm::dot(reference, normal) * normal);
}

}  // namespace

Plane::Plane(Vec3 point, Vec3 normal, int material)
    : Shape(material),
      point_(point),
      normal_(glm::normalize(normal)),
      uAxis_(textureUAxis(normal_)),
      vAxis_(glm::cross(normal_, uAxis_)) {}

bool Plane::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  if (!intersectPlane(ray, point_, normal_, tMin, hit.t, hit.t)) return false;
  hit.shape = this;
  return true;
}

SurfacePoint Plane::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  const Vec3 offset = position - point_;
  return {position, normal_, Vec2(glm::dot(offset, uAxis_), glm::dot(offset, vAxis_))};
}

}  // namespace rise
