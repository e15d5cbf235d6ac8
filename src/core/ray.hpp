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

// A ray with a NaN or an infinite component goes nowhere: it meets nothing,
// and the acceleration structures must not be handed it (their box tests
// would take it to meet every box).
inline bool isFinite(const Ray& ray) { return isFinite(ray.origin) && isFinite(ray.direction); }

}  // namespace rise
