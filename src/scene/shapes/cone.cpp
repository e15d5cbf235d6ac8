#include "scene/shapes/cone.hpp"

#include <algorithm>
#include <array>
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

// The side as quadrilaterals between rings around the axis, the last ring
// joined to the apex by triangles, and the base cap. The rings are there for
// Gouraud shading, whose colours are computed at the vertices alone: the
// light changes along the slant too. The side's normal is the same all along
// each line from the rim to the apex, and every normal of the side meets at
// the apex, which has none of its own. So the side's vertices weigh their
// normals by their distance from the axis, down to nothing at the apex
// (SurfaceVertex::normal): interpolated across a facet, the normal is then
// that of the line from the rim through the point, as on the cone itself.
void Cone::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  // Across the slant (apex - rim) and around the axis, out of the cone.
  const auto sideNormal = [&](const Vec3& direction) {
    return glm::normalize(height_ * direction + radius_ * axis_);
  };
  const int segments = segmentsPerTurn(settings.level);
  const int rings = std::max(1, settings.level / 2);
  const std::vector<Vec3> around = directionsAround(axis_, segments);
  // ring[j][k]: ring j, from the rim (0) up, at the k-th direction around.
  std::vector<std::vector<int>> ring(rings);
  for (int j = 0; j < rings; ++j) {
    const float up = static_cast<float>(j) / static_cast<float>(rings);
    for (int k = 0; k <= segments; ++k) {
      const Vec3& direction = around[k % segments];
      const Vec3 position = base_ + up * height_ * axis_ + (1.0f - up) * radius_ * direction;
      const Vec2 uv(turnAtStep(static_cast<float>(k), segments), up);
      ring[j].push_back(out.addVertex({position, (1.0f - up) * sideNormal(direction), uv}));
    }
  }
  for (int k = 0; k < segments; ++k) {
    for (int j = 0; j + 1 < rings; ++j)
      out.addConvexPolygon(
          std::array{ring[j][k], ring[j][k + 1], ring[j + 1][k + 1], ring[j + 1][k]});
    const Vec2 apexUv(turnAtStep(static_cast<float>(k) + 0.5f, segments), 1.0f);
    out.addTriangle(ring[rings - 1][k], ring[rings - 1][k + 1],
                    out.addVertex({apex_, Vec3(0.0f), apexUv}));
  }
  std::vector<int> cap;
  for (int k = 0; k < segments; ++k) {
    const Vec3 atRim = base_ + radius_ * around[k];
    cap.push_back(out.addVertex({atRim, -axis_, diskUv(atRim, base_, -axis_, radius_)}));
  }
  // The cap faces down the axis: its corners turn clockwise around it.
  std::reverse(cap.begin(), cap.end());
  out.addConvexPolygon(cap);
  out.enclosesSolid = true;
}

// The side's rings of quadrilaterals up to the apex, and the base's fan.
std::uint64_t Cone::tessellatedTriangles(int level) const {
  const auto segments = static_cast<std::uint64_t>(segmentsPerTurn(level));
  return segments * (2 * static_cast<std::uint64_t>(std::max(1, level / 2)) + 1);
}

}  // namespace rise
