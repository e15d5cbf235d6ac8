// How two polygons on the screen stand to each other, the questions depth
// sort asks of each pair: their extents in x, y and depth, on which side of a
// plane a polygon's corners lie, and whether their images overlap. Corners
// are raster positions in x and y and inverse depths w = 1/n in z, in which
// space planes stay planes.
#pragma once

#include <span>

#include "core/math.hpp"

namespace rise {

// Corners this close to a plane, relative to the polygon's nearest inverse
// depth, are on it: the corners two faces share lie on both faces' planes,
// up to rounding.
constexpr float kPlaneTolerance = 1e-5f;

// A polygon's screen extent and depth range (inverse depths: `farthest` is
// the smallest w).
struct Extent {
  Vec2 low, high;
  float farthest, nearest;
};

Extent extentOf(std::span<const Vec3> corners);

// Where the corners lie from a plane in screen space: wholly behind it (none
// in front), wholly in front (none behind), or both ways.
struct PlaneSides {
  bool someInFront = false;
  bool someBehind = false;
};

// `tolerance` is the polygon's own: the one its split uses too, so that a
// piece of a split never lies on both sides of the plane that cut it.
PlaneSides planeSides(std::span<const Vec3> corners, const glm::vec4& plane, float tolerance);

// Whether the images of two convex polygons overlap by more than a touch
// (separating axes).
bool imagesOverlap(std::span<const Vec3> a, std::span<const Vec3> b);

}  // namespace rise
