// Ritter's bounding sphere (J. Ritter, "An Efficient Bounding Sphere", in A.
// Glassner, ed., Graphics Gems, 1990, pp. 301-303), as in the original RISE
// report's pseudo-code: two passes over the points. The first finds the
// points of least and greatest x, y and z and takes the pair farthest apart
// as the first diameter; the second takes in each point still outside by
// moving the sphere towards it and widening it just enough.
//
// The sphere holds every point, and is found in linear time, but it is not
// the smallest one: it is typically 5 to 20% wider (the report calls it
// optimal; it is not).
#pragma once

#include <span>

#include "core/math.hpp"

namespace rise {

struct BoundingSphere {
  Vec3 centre{0.0f};
  float radius = 0.0f;
};

// The sphere around `points`, which must not be empty.
BoundingSphere ritterBoundingSphere(std::span<const Vec3> points);

}  // namespace rise
