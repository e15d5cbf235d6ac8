// Sutherland and Hodgman's polygon clipping (I. E. Sutherland and G. W.
// Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974): walk once around
// a convex polygon, keeping the corners on the wanted side of a plane and
// adding, on every edge that crosses it, the point where it crosses. The
// visible-surface algorithms clip with it against the view volume, and depth
// sort splits polygons with it along another polygon's plane.
#pragma once

#include <span>
#include <vector>

#include "core/math.hpp"

namespace rise {

// The plane a.x + b.y + c.z + d = 0 of the points p with signedDistance = 0,
// where signedDistance(plane, p) = a p.x + b p.y + c p.z + d (a distance
// scaled by |(a, b, c)|).
inline float signedDistance(const glm::vec4& plane, const Vec3& p) {
  return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w;
}

// Splits the convex polygon into its part where signedDistance >= 0
// (`positive`) and its part where it is <= 0 (`negative`); corners within
// `tolerance` of the plane belong to both. A part with fewer than three
// corners comes back empty. The point where an edge crosses is interpolated
// from its positive end towards its negative end, so that two polygons
// sharing an edge get the very same point, whichever way they run along it.
void splitPolygon(std::span<const Vec3> polygon, const glm::vec4& plane, float tolerance,
                  std::vector<Vec3>& positive, std::vector<Vec3>& negative);

}  // namespace rise
