// The quadratic equations behind the sphere, cylinder and cone intersections,
// solved without the cancellation of the textbook formula.
#pragma once

#include "core/math.hpp"

namespace rise {

// The real roots t0 <= t1 of a t^2 + 2 halfB t + c = 0, given its discriminant
// halfB^2 - a c. The root of larger magnitude comes from q = -(halfB +
// sign(halfB) sqrt(discriminant)) and the other from c / q, so that neither
// subtracts nearly equal numbers (Press et al., Numerical Recipes, 3rd ed.,
// section 5.6). When a = 0 one of them is the root of the linear equation and
// the other is infinite. Returns false when there is no real root.
bool solveQuadratic(float a, float halfB, float c, float discriminant, float& t0, float& t1);

// Where the line f + t d lies at distance sqrt(radiusSquared) from the origin:
// a sphere around the origin, or an infinite cylinder once f and d are
// projected across its axis. The discriminant is computed as
// a (r^2 - |f - (f.d / a) d|^2), the squared distance of the line from the
// origin, which stays accurate when the line starts far away (Haines et al.,
// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019).
// Returns false when the line does not come that close or does not move (d = 0).
// Inline: it is the innermost test of every sphere and cylinder.
inline bool solveLineAtDistance(Vec3 f, Vec3 d, float radiusSquared, float& t0, float& t1) {
  const float a = glm::dot(d, d);
  if (a == 0.0f) return false;
  const float halfB = glm::dot(f, d);
  const Vec3 closestApproach = f - (halfB / a) * d;
  const float discriminant = a * (radiusSquared - glm::dot(closestApproach, closestApproach));
  const float c = glm::dot(f, f) - radiusSquared;
  return solveQuadratic(a, halfB, c, discriminant, t0, t1);
}

}  // namespace rise
