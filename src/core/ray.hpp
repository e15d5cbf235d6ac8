#pragma once

#include "core/math.hpp"

namespace rise {

// A half-line origin + t * direction. The direction need not be unit length:
// a transformed shape intersects the ray in its own space without
// renormalising, so that t means the same in both spaces.
struct Ray {
  Vec3 origin;
  Vec3 direction;

  Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace rise
