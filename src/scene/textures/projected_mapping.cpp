#include "scene/textures/projected_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/textures/surface_mapping.hpp"

namespace rise {

namespace {

// The face a planar mapping projects from: the box's front, facing -z.
const Vec3 kPlanarFace(0.0f, 0.0f, -1.0f);

// How close to the axis a point is on it, as a fraction of the box's size.
constexpr float kOnAxis = 1e-5f;

// The box with each side of no length (a flat object's, across itself) as
// long as its longest side, so that every projection divides by a length.
Bounds3 withoutFlatSides(const Bounds3& bounds) {
  const Vec3 extent = bounds.extent();
  const float longest = std::max({extent.x, extent.y, extent.z, 1e-6f});
  Bounds3 solid = bounds;
  for (int axis = 0; axis < 3; ++axis) {
    if (extent[axis] > 0.0f) continue;
    solid.min[axis] -= 0.5f * longest;
    solid.max[axis] += 0.5f * longest;
  }
  return solid;
}

// Places turns (u in [0, 1)) on the shortest arc that covers them all, the
// ones past the seam beyond 1, so that interpolating between them goes the
// short way. Turns that no half turn covers lie around the axis, where
// interpolating u is wrong whichever way it goes: they all take their mean.
void onShortestArc(std::vector<float*>& turns) {
  if (turns.empty()) return;
  std::sort(turns.begin(), turns.end(), [](const float* a, const float* b) { return *a < *b; });
  // The arc starts after the widest gap between neighbours around the
  // circle: from the last across the seam to the first, or between two.
  float widest = *turns.front() + 1.0f - *turns.back();
  std::size_t start = 0;
  for (std::size_t i = 1; i < turns.size(); ++i) {
    if (*turns[i] - *turns[i - 1] <= widest) continue;
    widest = *turns[i] - *turns[i - 1];
    start = i;
  }
  for (std::size_t i = 0; i < start; ++i) *turns[i] += 1.0f;
  if (widest >= 0.5f) return;
  float sum = 0.0f;
  for (const float* turn : turns) sum += *turn;
  for (float* turn : turns) *turn = sum / static_cast<float>(turns.size());
}

}  // namespace

ProjectedMapping::ProjectedMapping(const Mapping& mapping, const Bounds3& bounds)
    : mapping_(mapping),
      bounds_(withoutFlatSides(bounds)),
      halfHeight_(0.5f * glm::dot(bounds_.extent(), glm::abs(mapping.axis))) {}

bool ProjectedMapping::turns() const {
  return mapping_.projection == Projection::Spherical ||
         mapping_.projection == Projection::Cylindrical;
}

Vec3 ProjectedMapping::faceProjectedFrom(const Vec3& normal) const {
  return mapping_.projection == Projection::Planar ? kPlanarFace : cubeFaceFacing(normal);
}

Vec2 ProjectedMapping::uvAt(const Vec3& position, const Vec3& normal) const {
  const Vec3 fromCentre = position - bounds_.centre();
  const Vec3& axis = mapping_.axis;
  if (mapping_.projection == Projection::Spherical) {
    const float distance = glm::length(fromCentre);
    return distance > 0.0f ? sphericalUv(axis, fromCentre / distance) : Vec2(0.0f, 0.5f);
  }
  // The flat ends of the box lie at v = 0 and 1 exactly, where rounding
  // would otherwise scatter points of a flat top past 1, to the repeated
  // texture's bottom row.
  if (mapping_.projection == Projection::Cylindrical)
    return {turnAroundAxis(axis, fromCentre),
            std::clamp(0.5f + glm::dot(fromCentre, axis) / (2.0f * halfHeight_), 0.0f, 1.0f)};
  return cubeFaceUv(position, faceProjectedFrom(normal), bounds_.min, bounds_.max);
}

void ProjectedMapping::tangentsAt(const Vec3& position, const Vec3& normal, Vec3& dpdu,
                                  Vec3& dpdv) const {
  const Vec3 fromCentre = position - bounds_.centre();
  const Vec3& axis = mapping_.axis;
  // The tangents of the surface the texture is projected from.
  Vec3 alongU, alongV;
  if (mapping_.projection == Projection::Spherical) {
    sphericalTangents(axis, fromCentre, alongU, alongV);
  } else if (mapping_.projection == Projection::Cylindrical) {
    alongU = turnTangent(axis, fromCentre - glm::dot(fromCentre, axis) * axis);
    alongV = (2.0f * halfHeight_) * axis;
  } else {
    cubeFaceTangents(faceProjectedFrom(normal), bounds_.min, bounds_.max, alongU, alongV);
  }
  projectedTangents(normal, alongU, alongV, dpdu, dpdv);
}

void ProjectedMapping::mapOnto(SurfacePoint& surface) const {
  surface.uv = uvAt(surface.position, surface.normal);
  tangentsAt(surface.position, surface.normal, surface.dpdu, surface.dpdv);
}

Vec2 ProjectedMapping::step(const Vec2& from, const Vec2& to) const {
  Vec2 difference = to - from;
  if (turns()) difference.x -= std::round(difference.x);
  return difference;
}

bool ProjectedMapping::isOnAxis(const Vec3& position) const {
  const Vec3 fromCentre = position - bounds_.centre();
  const Vec3 across = fromCentre - glm::dot(fromCentre, mapping_.axis) * mapping_.axis;
  return glm::length(across) <= kOnAxis * glm::length(bounds_.extent());
}

std::array<Vec2, 3> ProjectedMapping::cornerUvs(const std::array<Vec3, 3>& corners) const {
  const Vec3 normal = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
  std::array<Vec2, 3> uvs;
  for (int corner = 0; corner < 3; ++corner) uvs[corner] = uvAt(corners[corner], normal);
  if (!turns()) return uvs;
  std::vector<float*> turnsAround;
  for (int corner = 0; corner < 3; ++corner)
    if (!isOnAxis(corners[corner])) turnsAround.push_back(&uvs[corner].x);
  onShortestArc(turnsAround);
  float sum = 0.0f;
  for (const float* turn : turnsAround) sum += *turn;
  for (int corner = 0; corner < 3; ++corner) {
    if (!turnsAround.empty() && isOnAxis(corners[corner]))
      uvs[corner].x = sum / static_cast<float>(turnsAround.size());
  }
  return uvs;
}

}  // namespace rise
