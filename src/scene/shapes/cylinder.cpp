#include "scene/shapes/cylinder.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "scene/shapes/disk.hpp"
#include "scene/shapes/quadratic.hpp"
#include "scene/textures/surface_mapping.hpp"

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
  if (hit.primitive != kSide) {
    const Vec3 normal = hit.primitive == kTopCap ? axis_ : -axis_;
    const Vec3 center = hit.primitive == kTopCap ? top_ : base_;
    SurfacePoint surface(position, normal, diskUv(position, center, normal, radius_));
    diskTangents(normal, radius_, surface.dpdu, surface.dpdv);
    return surface;
  }
  const Vec3 across = acrossAxis(position - base_, axis_);
  const Vec3 normal = glm::normalize(across);
  const float height = glm::dot(position - base_, axis_);
  SurfacePoint surface(position, normal, {turnAroundAxis(axis_, normal), height / height_});
  surface.dpdu = turnTangent(axis_, across);
  surface.dpdv = height_ * axis_;
  return surface;
}

Bounds3 Cylinder::bounds() const {
  Bounds3 box = diskBounds(base_, axis_, radius_);
  box.grow(diskBounds(top_, axis_, radius_));
  return box;
}

// Flat rectangles around the side, with the side's normals at their corners,
// and a polygon for each cap. The side repeats its first column at the end,
// with u = 1 instead of 0, so that the texture has no jump at the seam.
void Cylinder::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  const int segments = segmentsPerTurn(settings.level);
  const std::vector<Vec3> around = directionsAround(axis_, segments);
  std::vector<int> bottom, top, baseCap, topCap;
  for (int k = 0; k <= segments; ++k) {
    const Vec3& direction = around[k % segments];
    const Vec3 atBase = base_ + radius_ * direction;
    const Vec3 atTop = top_ + radius_ * direction;
    const float u = turnAtStep(static_cast<float>(k), segments);
    bottom.push_back(out.addVertex({atBase, direction, {u, 0.0f}}));
    top.push_back(out.addVertex({atTop, direction, {u, 1.0f}}));
    if (k == segments) break;
    baseCap.push_back(out.addVertex({atBase, -axis_, diskUv(atBase, base_, -axis_, radius_)}));
    topCap.push_back(out.addVertex({atTop, axis_, diskUv(atTop, top_, axis_, radius_)}));
  }
  for (int k = 0; k < segments; ++k)
    out.addConvexPolygon(std::array{bottom[k], bottom[k + 1], top[k + 1], top[k]});
  // The base cap faces down the axis: its corners turn the other way.
  std::reverse(baseCap.begin(), baseCap.end());
  out.addConvexPolygon(baseCap);
  out.addConvexPolygon(topCap);
  out.enclosesSolid = true;
}

// The side's quadrilaterals and the two caps' fans.
std::uint64_t Cylinder::tessellatedTriangles(int level) const {
  return 4 * static_cast<std::uint64_t>(segmentsPerTurn(level));
}

}  // namespace rise
