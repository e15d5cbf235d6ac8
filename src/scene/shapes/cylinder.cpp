#include "scene/shapes/cylinder.hpp"

#include <algorithm>
#include <array>
#include <vector>

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

Bounds3 Cylinder::bounds() const {
  Bounds3 box = diskBounds(base_, axis_, radius_);
  box.grow(diskBounds(top_, axis_, radius_));
  return box;
}

// Flat rectangles around the side, with the side's normals at their corners,
// and a polygon for each cap.
void Cylinder::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  std::vector<int> bottom, top, baseCap, topCap;
  for (const Vec3& direction : directionsAround(axis_, segmentsPerTurn(settings.level))) {
    bottom.push_back(out.addVertex({base_ + radius_ * direction, direction}));
    top.push_back(out.addVertex({top_ + radius_ * direction, direction}));
    baseCap.push_back(out.addVertex({base_ + radius_ * direction, -axis_}));
    topCap.push_back(out.addVertex({top_ + radius_ * direction, axis_}));
  }
  const std::size_t segments = bottom.size();
  for (std::size_t k = 0; k < segments; ++k) {
    const std::size_t next = (k + 1) % segments;
    out.addConvexPolygon(std::array{bottom[k], bottom[next], top[next], top[k]});
  }
  // The base cap faces down the axis: its corners turn the other way.
  std::reverse(baseCap.begin(), baseCap.end());
  out.addConvexPolygon(baseCap);
  out.addConvexPolygon(topCap);
  out.enclosesSolid = true;
}

}  // namespace rise
