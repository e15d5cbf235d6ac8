#include "scene/shapes/quadratic.hpp"

#include <cmath>
#include <utility>

namespace rise {

bool solveQuadratic(float a, float halfB, float c, float discriminant, float& t0, float& t1) {
  if (!(discriminant >= 0.0f)) return false;
  const float q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
  if (q == 0.0f) {
    // halfB and the discriminant are both zero, so a c = 0: with a = 0 every t
    // or none solves it, which only a ray lying in the surface can do.
    if (a == 0.0f) return false;
    t0 = t1 = 0.0f;
    return true;
  }
  t0 = c / q;
  t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace rise
