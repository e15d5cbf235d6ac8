// A small, fast, statistically good random number generator: PCG32 (M. E.
// O'Neill, "PCG: A family of simple fast space-efficient statistically good
// algorithms for random number generation", 2014). RISE seeds one per pixel
// from the render's seed and the pixel's coordinates, so every pixel draws the
// same numbers whichever thread renders it, and a different seed gives
// different noise.
#pragma once

#include <cstdint>

namespace rise {

class Rng {
 public:
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) {
    increment_ = (stream << 1u) | 1u;
    nextBits();
    state_ += seed;
    nextBits();
  }

  std::uint32_t nextBits() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + increment_;
    const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rotation = static_cast<std::uint32_t>(old >> 59u);
    return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, which a float holds exactly.
  float uniform() { return static_cast<float>(nextBits() >> 8) * 0x1.0p-24f; }

  // Uniform in {0, ..., bound - 1}, without modulo bias.
  std::uint32_t below(std::uint32_t bound) {
    const std::uint32_t threshold = (0u - bound) % bound;
    for (;;) {
      const std::uint32_t bits = nextBits();
      if (bits >= threshold) return bits % bound;
    }
  }

 private:
  std::uint64_t state_ = 0;
  std::uint64_t increment_ = 1;
};

// A well-mixed 64-bit value from a render seed and a pixel (SplitMix64's
// finaliser), so that neighbouring pixels get unrelated sequences.
inline std::uint64_t pixelSeed(std::uint64_t seed, int x, int y) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (1u + static_cast<std::uint32_t>(x)) +
                    0xD1B54A32D192ED03ULL * (1u + static_cast<std::uint32_t>(y));
  z = (z ^ (z >> 30u)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27u)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31u);
}

}  // namespace rise
