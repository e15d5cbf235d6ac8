// Which pixel centres c + 1/2 a range of raster positions holds.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.hpp"

namespace rise {

// Far beyond any image's side, and still exactly a whole number as a float
// and an int: a corner projected towards infinity (a shadow volume's far
// side) still names a row or column of ints.
inline constexpr float kFarthestPixel = 1 << 24;

// A corner with no place on the screen (NaN) bounds no pixels and no edges.
inline bool hasNoPlace(const Vec3& corner) { return std::isnan(corner.x) || std::isnan(corner.y); }

// The first centre at or past `low`. A position with no place (NaN) lies past
// every pixel, so that the range it starts holds none.
inline int firstCentreFrom(float low) {
  if (std::isnan(low)) return static_cast<int>(kFarthestPixel);
  return static_cast<int>(std::ceil(std::clamp(low, -kFarthestPixel, kFarthestPixel) - 0.5f));
}

// One past the last centre at or before `high`.
inline int pastLastCentreTo(float high) {
  if (std::isnan(high)) return -static_cast<int>(kFarthestPixel);
  return static_cast<int>(std::floor(std::clamp(high, -kFarthestPixel, kFarthestPixel) - 0.5f)) + 1;
}

}  // namespace rise
