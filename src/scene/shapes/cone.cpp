#include "scene/shapes/cone.hpp"

#include <algorithm>
#include <vector>

#include "scene/shapes/disk.hpp"
#include "scene/shapes/quadratic.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {

namespace {

// The primitive a cone hit records.
enum Part : int { kSide, kBaseCap };

}  // namespace

Cone::Cone(Vec3 base, Vec3 axis, float radius, float height, int material)
    : Shape(material),
      base_(base),
      axis_(glm::normalize(axis)),
      radius_(radius),
      height_(height),
      apex_(base_ + height * axis_),
      slopeFactor_(1.0f + (radius / height) * (radius / height)) {}

bool Cone::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  float nearest = hit.t;
  int part = -1;
  // Heights are measured along the axis from the apex: the cone lies in
  // [-height, 0], the other nappe of the quadric above 0.
  const Vec3 fromApex = ray.origin - apex_;
  const float heightAtOrigin = glm::dot(fromApex, axis_);
  const float heightRate = glm::dot(ray.direction, axis_);
  const float a = glm::dot(ray.direction, ray.direction) - slopeFactor_ * heightRate * heightRate;
  const float halfB =
      glm::dot(fromApex, ray.direction) - slopeFactor_ * heightAtOrigin * heightRate;
  const float c = glm::dot(fromApex, fromApex) - slopeFactor_ * heightAtOrigin * heightAtOrigin;
  float roots[2];
  if (solveQuadratic(a, halfB, c, halfB * halfB - a * c, roots[0], roots[1])) {
    for (float t : roots) {
      const float height = heightAtOrigin + t * heightRate;
      if (t > tMin && t < nearest && height >= -height_ && height <= 0.0f) {
        nearest = t;
        part = kSide;
        break;
      }
    }
  }
  float tCap;
  if (intersectDisk(ray, base_, axis_, radius_ * radius_, tMin, nearest, tCap)) {
    nearest = tCap;
    part = kBaseCap;
  }
  if (part < 0) return false;
  hit.t = nearest;
  hit.shape = this;
  hit.primitive = part;
  return true;
}

SurfacePoint Cone::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  if (hit.primitive == kBaseCap) {
    SurfacePoint surface(position, -axis_, diskUv(position, base_, -axis_, radius_));
    diskTangents(-axis_, radius_, surface.dpdu, surface.dpdv);
    return surface;
  }
  // The gradient of the quadric, which points out of the cone.
  const Vec3 fromApex = position - apex_;
  const float heightBelowApex = -glm::dot(fromApex, axis_);
  const Vec2 uv(turnAroundAxis(axis_, fromApex), 1.0f - heightBelowApex / height_);
  const Vec3 gradient = fromApex + slopeFactor_ * heightBelowApex * axis_;
  // The apex has no tangent plane; the axis stands in for its normal.
  if (glm::dot(gradient, gradient) == 0.0f) return {position, axis_, uv};
  SurfacePoint surface(position, glm::normalize(gradient), uv);
  // Up the slant, from the rim (v = 0) to the apex (v = 1).
  const Vec3 across = fromApex + heightBelowApex * axis_;
  surface.dpdu = turnTangent(axis_, across);
  surface.dpdv = -fromApex / (1.0f - uv.y);
  return surface;
}

Bounds3 Cone::bounds() const {
  Bounds3 box = diskBounds(base_, axis_, radius_);
  box.grow(apex_);
  return box;
}

// Triangles from the base circle to the apex, and the base cap. The apex has
// no normal of its own: each triangle's apex corner takes the side's normal
// halfway across the triangle.
void Cone::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  // Across the slant (apex - rim) and around the axis, out of the cone.
  const auto sideNormal = [&](const Vec3& direction) {
    return glm::normalize(height_ * direction + radius_ * axis_);
  };
  const int segments = segmentsPerTurn(settings.level);
  const std::vector<Vec3> around = directionsAround(axis_, segments);
  const auto uAt = [segments](int k, float fraction) {
    return turnAtStep(static_cast<float>(k) + fraction, segments);
  };
  std::vector<int> cap;
  for (int k = 0; k < segments; ++k) {
    const Vec3& direction = around[k];
    const Vec3& nextDirection = around[(k + 1) % segments];
    const Vec3 atRim = base_ + radius_ * direction;
    const int rim = out.addVertex({atRim, sideNormal(direction), {uAt(k, 0.0f), 0.0f}});
    const int nextRim = out.addVertex(
        {base_ + radius_ * nextDirection, sideNormal(nextDirection), {uAt(k, 1.0f), 0.0f}});
    const int apex = out.addVertex(
        {apex_, sideNormal(glm::normalize(direction + nextDirection)), {uAt(k, 0.5f), 1.0f}});
    out.addTriangle(rim, nextRim, apex);
    cap.push_back(out.addVertex({atRim, -axis_, diskUv(atRim, base_, -axis_, radius_)}));
  }
  // The cap faces down the axis: its corners turn clockwise around it.
  std::reverse(cap.begin(), cap.end());
  out.addConvexPolygon(cap);
  out.enclosesSolid = true;
}

}  // namespace rise
