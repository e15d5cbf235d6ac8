#include "raster/polygon_relations.hpp"

#include <algorithm>

#include "raster/polygon_clipping.hpp"

namespace rise {
namespace {

// Images overlapping by less than this, in pixels, only touch.
constexpr float kOverlapTolerance = 1e-4f;

// Whether an edge of `a`, as a separating axis, keeps the two convex images
// apart.
bool separatedByAnEdgeOf(std::span<const Vec3> a, std::span<const Vec3> b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 edge = Vec2(a[nextCorner(i, a.size())]) - Vec2(a[i]);
    const float length = glm::length(edge);
    if (length == 0.0f) continue;
    const Vec2 axis = Vec2(-edge.y, edge.x) / length;
    float lowA = kInfinity, highA = -kInfinity, lowB = kInfinity, highB = -kInfinity;
    for (const Vec3& corner : a) {
      lowA = std::min(lowA, glm::dot(axis, Vec2(corner)));
      highA = std::max(highA, glm::dot(axis, Vec2(corner)));
    }
    for (const Vec3& corner : b) {
      lowB = std::min(lowB, glm::dot(axis, Vec2(corner)));
      highB = std::max(highB, glm::dot(axis, Vec2(corner)));
    }
    if (highA <= lowB + kOverlapTolerance || highB <= lowA + kOverlapTolerance) return true;
  }
  return false;
}

}  // namespace

Extent extentOf(std::span<const Vec3> corners) {
  Extent extent{Vec2(kInfinity), Vec2(-kInfinity), kInfinity, -kInfinity};
  for (const Vec3& corner : corners) {
    extent.low = glm::min(extent.low, Vec2(corner));
    extent.high = glm::max(extent.high, Vec2(corner));
    extent.farthest = std::min(extent.farthest, corner.z);
    extent.nearest = std::max(extent.nearest, corner.z);
  }
  return extent;
}

PlaneSides planeSides(std::span<const Vec3> corners, const glm::vec4& plane, float tolerance) {
  PlaneSides sides;
  for (const Vec3& corner : corners) {
    const float distance = signedDistance(plane, corner);
    sides.someInFront |= distance > tolerance;
    sides.someBehind |= distance < -tolerance;
  }
  return sides;
}

bool imagesOverlap(std::span<const Vec3> a, std::span<const Vec3> b) {
  return !separatedByAnEdgeOf(a, b) && !separatedByAnEdgeOf(b, a);
}

}  // namespace rise
