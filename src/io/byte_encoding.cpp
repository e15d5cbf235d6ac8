#include "io/byte_encoding.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rise {

std::uint8_t byteFromLinear(float linear, Encoding encoding) {
  // The zero comes first so that a NaN colour becomes black.
  float value = std::min(std::max(0.0f, linear), 1.0f);
  if (encoding == Encoding::Srgb) value = srgbFromLinear(value);
  return static_cast<std::uint8_t>(std::lround(value * 255.0f));
}

namespace {

// The smallest value in [0, 1] stored as `level` or above, found by halving
// the non-negative floats between 0 and 1, whose bit patterns are in the
// order of their values; the levels grow with the value.
float levelStartOf(int level, Encoding encoding) {
  std::uint32_t below = std::bit_cast<std::uint32_t>(0.0f);  // stored below `level`
  std::uint32_t atOrAbove = std::bit_cast<std::uint32_t>(1.0f);
  while (atOrAbove - below > 1) {
    const std::uint32_t middle = below + (atOrAbove - below) / 2;
    if (byteFromLinear(std::bit_cast<float>(middle), encoding) >= level)
      atOrAbove = middle;
    else
      below = middle;
  }
  return std::bit_cast<float>(atOrAbove);
}

}  // namespace

ByteEncoder::ByteEncoder(Encoding encoding) {
  levelStarts_[0] = 0.0f;
  for (int level = 1; level < 256; ++level) levelStarts_[level] = levelStartOf(level, encoding);
  levelStarts_[256] = std::numeric_limits<float>::infinity();
  const auto levelOf = [&](float value) {
    return std::upper_bound(levelStarts_.begin(), levelStarts_.end(), value) -
           levelStarts_.begin() - 1;
  };
  for (std::size_t range = 0; range < kRanges; ++range) {
    const auto first = static_cast<std::uint32_t>(range << kRangeShift);
    const auto lowest = levelOf(std::bit_cast<float>(first));
    const float highest =
        std::min(1.0f, std::bit_cast<float>(first + (std::uint32_t{1} << kRangeShift) - 1));
    if (levelOf(highest) > lowest + 1)
      throw std::logic_error("ByteEncoder: a range of values holds the start of two levels");
    rangeLevels_[range] = static_cast<std::uint8_t>(lowest);
  }
}

const ByteEncoder& byteEncoder(Encoding encoding) {
  static const ByteEncoder srgb(Encoding::Srgb);
  static const ByteEncoder linear(Encoding::Linear);
  return encoding == Encoding::Srgb ? srgb : linear;
}

}  // namespace rise
