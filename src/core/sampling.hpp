// Where the samples of a pixel go. Anti-aliasing takes several samples in each
// pixel and averages them; how they are placed decides what error remains:
//
//   none      one sample at the pixel's centre
//   regular   an n x m grid of cell centres: aliasing only moves to finer detail
//   random    uniform positions: no aliasing, but clumps and holes give noise
//   jittered  one random position in each cell of the grid (the original RISE
//             report's 16 regions; Cook 1984): the noise of random, much less
//   adaptive  Whitted's (1980) refinement: the pixel's corners first, then
//             quarters, wherever the corner colours differ by more than a
//             threshold
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.hpp"
#include "core/random.hpp"

namespace rise {

enum class SamplePattern { None, Regular, Jittered, Random, Adaptive };

// How samples become pixels: each pixel averages the samples near it,
// weighted by the filter centred on it. The box (radius 1/2) takes its own
// samples alone, equally; the tent (radius 1) and the Gaussian (standard
// deviation 1/2, radius 3/2) also take their neighbours' nearest samples,
// trading a little sharpness for smoother edges.
enum class FilterKind { Box, Tent, Gaussian };

inline constexpr SamplePattern kAllPatterns[] = {SamplePattern::None, SamplePattern::Regular,
                                                 SamplePattern::Jittered, SamplePattern::Random,
                                                 SamplePattern::Adaptive};
inline constexpr FilterKind kAllFilters[] = {FilterKind::Box, FilterKind::Tent,
                                             FilterKind::Gaussian};

std::string_view toString(SamplePattern pattern);
std::string_view toString(FilterKind filter);

// How each pixel is sampled, as the scene file's `image` block or the command
// line sets it.
struct PixelSampling {
  int samples = 1;
  SamplePattern pattern = SamplePattern::None;
  FilterKind filter = FilterKind::Box;
  // Adaptive: the largest colour difference between a square's corners that
  // is left unrefined.
  float adaptiveThreshold = 0.05f;
};

// The sampling that results from choosing a count, a pattern or both over
// `base` (as the command line does over the scene file's): a count alone keeps
// the base's pattern, or takes jittered over none; a pattern alone keeps the
// base's count, or takes the original RISE report's 16 over a single sample
// (and none takes 1).
PixelSampling chooseSampling(PixelSampling base, std::optional<int> samples,
                             std::optional<SamplePattern> pattern);

// The most samples a pixel takes: a grid of 256 x 256.
inline constexpr int kMostSamples = 65536;

// What is wrong with a sampling, for a message ("... ; expected ..."), or an
// empty string when it can be rendered.
std::string samplingProblem(const PixelSampling& sampling);

// The columns and rows of the grid closest to square that holds exactly n
// cells: 16 -> 4 x 4, 8 -> 4 x 2, 7 -> 7 x 1.
struct GridShape {
  int columns;
  int rows;
};
GridShape gridShape(int n);

// Fills `positions` with n positions in the unit square, placed by `pattern`
// (not Adaptive, which places its samples as it goes). Filling a vector the
// caller keeps saves an allocation per pixel.
void samplePositions(SamplePattern pattern, int n, Rng& rng, std::vector<Vec2>& positions);

// Whether samplePositions puts the samples in the same places in every pixel,
// drawing nothing from the generator: at the centre, or on a regular grid.
inline bool placesAlikeInEveryPixel(SamplePattern pattern) {
  return pattern == SamplePattern::None || pattern == SamplePattern::Regular;
}

// Fills `values` with n jittered values in [0, 1): one in each of n equal
// intervals, in order.
void jitteredValues(int n, Rng& rng, std::vector<float>& values);

// Puts the items in a uniformly random order (Fisher-Yates).
template <typename T>
void shuffle(std::vector<T>& items, Rng& rng) {
  for (std::size_t i = items.size(); i > 1; --i)
    std::swap(items[i - 1], items[rng.below(static_cast<std::uint32_t>(i))]);
}

}  // namespace rise
