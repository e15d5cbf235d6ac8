// The samples of a pixel, each a point in several dimensions, after Cook
// ("Stochastic sampling in computer graphics", ACM TOG 5(1), 1986): where in
// the pixel it lies, placed by the render's pattern (core/sampling.hpp), and
// the dimensions an algorithm asks of it beyond that: values in the unit
// square (a point of the lens, of an area light, a direction around a
// mirror's) and values in [0, 1) (an instant of the shutter interval). Each
// dimension's n values are stratified on its own (jittered, or uniformly
// random with the random pattern) and then shuffled apart, so that every
// dimension is well spread and no two are correlated: the sample in the
// pixel's top-left cell does not always take the lens's top-left too. A
// sample asked for more dimensions than were laid out, as a path deeper than
// its first surface is, gets uniformly random values; so does a sample taken
// alone, as adaptive supersampling takes them.
//
// Warps (core/warps.hpp) carry the square's values onto the domains
// sampled.
#pragma once

#include <vector>

#include "core/math.hpp"
#include "core/random.hpp"
#include "core/sampling.hpp"

namespace rise {

// The dimensions each sample takes beyond where in the pixel it lies.
struct SampleLayout {
  int squares = 0;    // values in the unit square
  int intervals = 0;  // values in [0, 1)
};

class SampleValues;

class Sampler {
 public:
  explicit Sampler(SampleLayout layout);

  // Lays out the n samples of a pixel, as `sampling` says (any pattern but
  // the adaptive, which places its samples as it goes): where each lies in
  // the pixel, from its top-left corner, and then each dimension of the
  // layout in turn, the squares' before the intervals'.
  const std::vector<Vec2>& startPixel(const PixelSampling& sampling, Rng& rng);

  // Sample i's values, handed out in the order asked; `rng` gives those
  // beyond the layout.
  SampleValues valuesOf(int sample, Rng& rng) const;

 private:
  friend class SampleValues;

  int samples_ = 0;
  std::vector<Vec2> pixel_;
  std::vector<std::vector<Vec2>> squares_;
  std::vector<std::vector<float>> intervals_;
};

// One sample's values beyond its place in the pixel: next2D and next1D hand
// out its squares' and its intervals' values in their order, then uniformly
// random ones.
class SampleValues {
 public:
  // A sample taken alone: every value uniformly random.
  explicit SampleValues(Rng& rng) : rng_(rng) {}

  Vec2 next2D();
  float next1D();

 private:
  friend class Sampler;
  SampleValues(const Sampler& sampler, int sample, Rng& rng)
      : sampler_(&sampler), sample_(sample), rng_(rng) {}

  const Sampler* sampler_ = nullptr;
  int sample_ = 0;
  std::size_t square_ = 0, interval_ = 0;
  Rng& rng_;
};

}  // namespace rise
