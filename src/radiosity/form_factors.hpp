// Form factors: the share of the light leaving one surface that reaches
// another, a matter of geometry alone (Goral, Torrance, Greenberg and
// Battaile 1984). From a small area dA_j around a point to a surface A_i,
//   F(dA_j -> A_i) = integral over A_i of cos(theta_j) cos(theta_i) / (pi r^2) dA_i,
// the angles between each surface's normal and the line joining them.
#pragma once

#include <array>
#include <cmath>

#include "core/math.hpp"

namespace rise {

// The form factor from a point (its unit normal `normal`) to a disc of area
// `area` centred at `centre` (unit normal `centreNormal`) facing it, seen
// whole: cos cos area / (pi r^2 + area), the disc's closed form on its axis
// (Wallace, Elmquist and Haines, "A ray tracing algorithm for progressive
// radiosity", SIGGRAPH 1989), which stays finite as the point nears the disc.
// Surfaces are taken two-sided: each cosine is taken whatever the side.
inline float formFactorToDisc(const Vec3& point, const Vec3& normal, const Vec3& centre,
                              const Vec3& centreNormal, float area) {
  const Vec3 offset = centre - point;
  const float distanceSquared = glm::dot(offset, offset);
  if (!(distanceSquared > 0.0f)) return 0.0f;
  const Vec3 direction = offset / std::sqrt(distanceSquared);
  const float cosines =
      std::abs(glm::dot(normal, direction)) * std::abs(glm::dot(centreNormal, direction));
  return cosines * area / (kPi * distanceSquared + area);
}

// The form factor from a point to a triangle: the disc's, where the
// triangle is small beside its distance; else the sum over the four triangles its sides' midpoints
// cut it into (down to `depth` times), so that neighbouring elements, which the disc's form would
// count too much or too little, still sum right.
inline float formFactorToTriangle(const Vec3& point, const Vec3& normal,
                                  const std::array<Vec3, 3>& corners, const Vec3& cornersNormal,
                                  int depth = 8) {
  const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0f;
  const float area =
      0.5f * glm::length(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
  const Vec3 offset = centre - point;
  // Near: within four times the triangle's size.
  if (depth == 0 || glm::dot(offset, offset) > 16.0f * area)
    return formFactorToDisc(point, normal, centre, cornersNormal, area);
  const Vec3 ab = 0.5f * (corners[0] + corners[1]), bc = 0.5f * (corners[1] + corners[2]),
             ca = 0.5f * (corners[2] + corners[0]);
  float sum = 0.0f;
  for (const std::array<Vec3, 3>& quarter :
       {std::array<Vec3, 3>{corners[0], ab, ca}, std::array<Vec3, 3>{ab, corners[1], bc},
        std::array<Vec3, 3>{ca, bc, corners[2]}, std::array<Vec3, 3>{ab, bc, ca}})
    sum += formFactorToTriangle(point, normal, quarter, cornersNormal, depth - 1);
  return sum;
}

}  // namespace rise
