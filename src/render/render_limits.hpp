// The limits of a render: what RISE refuses before it starts, or stops when
// it is reached, so that no scene and no setting makes a render run for
// hours or fill the memory. Each is documented in the README's Limits.
#pragma once

#include <cstdint>
#include <stdexcept>

namespace rise {

// A render that would exceed a limit; the message names the value and the
// limit, and what to do instead. The command line exits with status 2.
class RenderLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Depth sort compares pairs of polygons, as many as the square of their
// number for a scene where every polygon overlaps every other, and splits
// those it cannot order: about a minute of comparisons, and the pieces of
// some hundreds of megabytes.
inline constexpr std::uint64_t kMostDepthSortComparisons = 2'000'000'000;
inline constexpr std::uint64_t kMostDepthSortSplits = 2'000'000;

}  // namespace rise
