#include "core/sampling.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rise {
namespace {

// The largest float below 1: (cell + u) / cells can round up to 1 itself.
constexpr float kBelowOne = 0x1.fffffep-1f;

float cellPosition(int cell, float offset, int cells) {
  return std::min(kBelowOne, (static_cast<float>(cell) + offset) / static_cast<float>(cells));
}

}  // namespace

std::string_view toString(SamplePattern pattern) {
  switch (pattern) {
    case SamplePattern::None:
      return "none";
    case SamplePattern::Regular:
      return "regular";
    case SamplePattern::Jittered:
      return "jittered";
    case SamplePattern::Random:
      return "random";
    case SamplePattern::Adaptive:
      return "adaptive";
  }
  return "?";
}

std::string_view toString(FilterKind filter) {
  switch (filter) {
    case FilterKind::Box:
      return "box";
    case FilterKind::Tent:
      return "tent";
    case FilterKind::Gaussian:
      return "gaussian";
  }
  return "?";
}

PixelSampling chooseSampling(PixelSampling base, std::optional<int> samples,
                             std::optional<SamplePattern> pattern) {
  constexpr int kReportSamples = 16;
  if (samples) {
    base.samples = *samples;
    if (!pattern && base.pattern == SamplePattern::None && *samples > 1)
      base.pattern = SamplePattern::Jittered;
  }
  if (pattern) {
    base.pattern = *pattern;
    if (!samples && *pattern == SamplePattern::None) base.samples = 1;
    if (!samples && *pattern != SamplePattern::None && base.samples == 1)
      base.samples = kReportSamples;
  }
  return base;
}

namespace {

bool isPowerOfFour(int n) {
  while (n > 1 && n % 4 == 0) n /= 4;
  return n == 1;
}

}  // namespace

std::string samplingProblem(const PixelSampling& sampling) {
  if (sampling.samples < 1 || sampling.samples > kMostSamples)
    return std::to_string(sampling.samples) + " samples; expected 1 to " +
           std::to_string(kMostSamples) + " samples a pixel";
  if (sampling.pattern == SamplePattern::None && sampling.samples > 1)
    return std::to_string(sampling.samples) +
           " samples with the pattern 'none', which takes one sample at the pixel's centre; "
           "expected a pattern to place them: regular, jittered, random or adaptive";
  if (sampling.pattern == SamplePattern::Adaptive && !isPowerOfFour(sampling.samples))
    return std::to_string(sampling.samples) +
           " samples with the adaptive pattern; expected 1, 4, 16, 64 or 256, as each level of "
           "refinement splits a square into four";
  if (sampling.pattern == SamplePattern::Adaptive && sampling.filter != FilterKind::Box)
    return "the " + std::string(toString(sampling.filter)) +
           " filter with the adaptive pattern, which averages its own squares; expected the box "
           "filter, or another pattern";
  return {};
}

GridShape gridShape(int n) {
  int rows = static_cast<int>(std::sqrt(static_cast<double>(n)));
  while (n % rows != 0) --rows;
  return {n / rows, rows};
}

void samplePositions(SamplePattern pattern, int n, Rng& rng, std::vector<Vec2>& positions) {
  assert(pattern != SamplePattern::Adaptive);
  positions.clear();
  if (n == 1 && pattern != SamplePattern::Random) {
    // One cell: its centre, or a random point in it.
    const bool jitter = pattern == SamplePattern::Jittered;
    positions.emplace_back(jitter ? rng.uniform() : 0.5f, jitter ? rng.uniform() : 0.5f);
  } else if (pattern == SamplePattern::None) {
    positions.assign(n, Vec2(0.5f));
  } else if (pattern == SamplePattern::Random) {
    for (int i = 0; i < n; ++i) positions.emplace_back(rng.uniform(), rng.uniform());
  } else {
    const GridShape grid = gridShape(n);
    const bool jitter = pattern == SamplePattern::Jittered;
    for (int row = 0; row < grid.rows; ++row) {
      for (int column = 0; column < grid.columns; ++column) {
        const float u = jitter ? rng.uniform() : 0.5f;
        const float v = jitter ? rng.uniform() : 0.5f;
        positions.emplace_back(cellPosition(column, u, grid.columns),
                               cellPosition(row, v, grid.rows));
      }
    }
  }
}

void jitteredValues(int n, Rng& rng, std::vector<float>& values) {
  values.resize(n);
  for (int i = 0; i < n; ++i) values[i] = cellPosition(i, rng.uniform(), n);
}

}  // namespace rise
