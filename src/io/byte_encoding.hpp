// Linear colour values as the 8-bit levels that PNG and PPM store. A level
// is found in a table of the values at which each level starts, by eight
// comparisons, instead of by a power (sRGB's curve) and a rounding per
// value: the same level, found many times faster.
#pragma once

#include <array>
#include <cstdint>

#include "io/image_io.hpp"

namespace rise {

// The stored level of a linear value, computed directly: clamped to [0, 1]
// (NaN to 0), encoded, rounded to the nearest of the 256 levels.
std::uint8_t byteFromLinear(float linear, Encoding encoding);

class ByteEncoder {
 public:
  explicit ByteEncoder(Encoding encoding);

  // byteFromLinear(linear, encoding), for every float.
  std::uint8_t operator()(float linear) const {
    // The zero comes first so that a NaN becomes black.
    const float value = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;
    int level = 0;
    for (int step = 128; step > 0; step /= 2)
      if (levelStarts_[level + step] <= value) level += step;
    return static_cast<std::uint8_t>(level);
  }

  // The smallest value stored as `level`.
  float levelStart(int level) const { return levelStarts_[level]; }

 private:
  std::array<float, 256> levelStarts_;
};

// The encoder of each encoding, made once.
const ByteEncoder& byteEncoder(Encoding encoding);

}  // namespace rise
