#pragma once

#include "core/math.hpp"

namespace rise {

// A half-line origin + t * direction, at one instant while the camera's
// shutter is open. The direction need not be unit length: a transformed shape
// intersects the ray in its own space without renormalising, so that t means
// the same in both spaces.
struct Ray {
  Vec3 origin;
  Vec3 direction;
  float time = 0.0f;  // when the ray travels: moving shapes are where they are then

  Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace rise
