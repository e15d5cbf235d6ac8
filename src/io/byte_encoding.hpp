// Linear colour values as the 8-bit levels that PNG and PPM store. A level
// is found from the values at which each level starts, instead of by a power
// (sRGB's curve) and a rounding per value: the same level, found many times
// faster. A value's leading bits (its exponent and the top of its mantissa)
// pick a narrow range of values, whose lowest level a second table holds;
// no range holds the start of two levels, so one comparison, without a
// branch, finishes.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
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
    const int level = rangeLevels_[std::bit_cast<std::uint32_t>(value) >> kRangeShift];
    return static_cast<std::uint8_t>(level + (levelStarts_[level + 1] <= value ? 1 : 0));
  }

  // The smallest value stored as `level`.
  float levelStart(int level) const { return levelStarts_[level]; }

 private:
  // The floats of [0, 1] fall in about 2^14 ranges, 128 to each power of two.
  static constexpr int kRangeShift = 16;
  static constexpr std::size_t kRanges = (std::bit_cast<std::uint32_t>(1.0f) >> kRangeShift) + 1;

  std::array<float, 257> levelStarts_;             // and past the last level, infinity
  std::array<std::uint8_t, kRanges> rangeLevels_;  // the level of each range's lowest value
};

// The encoder of each encoding, made once.
const ByteEncoder& byteEncoder(Encoding encoding);

}  // namespace rise
