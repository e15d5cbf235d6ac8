#include "scene/shapes/cylinder.hpp"

#include "scene/shapes/disk.hpp"
#include "scene/shapes/quadratic.hpp"

namespace rise {

namespace {

// The primitive a cylinder hit records.
enum Part : int { kSide, kBaseCap, kTopCap };

Vec3 acrossAxis(Vec3 v, Vec3 unitAxis) { return v - glm::dot(v, unitAxis) * unitAxis; }

}  // namespace

Cylinder::Cylinder(Vec3 base, Vec3 axis, float radius, float height, int material)
    : Shape(material),
      base_(base),
      axis_(glm::normalize(axis)),
      radius_(radius),
      height_(height),
      top_(base_ + height * axis_) {}

bool Cylinder::intersect(const Ray& ray, float tMin, Hit& hit,
                         IntersectionCounters& counters) const {
  ++counters.tests;
  const float radiusSquared = radius_ * radius_;
  float nearest = hit.t;
  int part = -1;
  const Vec3 fromBase = ray.origin - base_;
  const float heightAtOrigin = glm::dot(fromBase, axis_);
  const float heightRate = glm::dot(ray.direction, axis_);
  float roots[2];
  if (solveLineAtDistance(acrossAxis(fromBase, axis_), acrossAxis(ray.direction, axis_),
                          radiusSquared, roots[0], roots[1])) {
    for (float t : roots) {
      const float height = heightAtOrigin + t * heightRate;
      if (t > tMin && t < nearest && height >= 0.0f && height <= height_) {
        nearest = t;
        part = kSide;
        break;
      }
    }
  }
  float tCap;
  if (intersectDisk(ray, base_, axis_, radiusSquared, tMin, nearest, tCap)) {
    nearest = tCap;
    part = kBaseCap;
  }
  if (intersectDisk(ray, top_, axis_, radiusSquared, tMin, nearest, tCap)) {
    nearest = tCap;
    part = kTopCap;
  }
  if (part < 0) return false;
  hit.t = nearest;
  hit.shape = this;
  hit.primitive = part;
  return true;
}

SurfacePoint Cylinder::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  switch (hit.primitive) {
    case kBaseCap:
      return {position, -axis_};
    case kTopCap:
      return {position, axis_};
    default:
      return {position, glm::normalize(acrossAxis(position - base_, axis_))};
  }
}

}  // namespace rise
