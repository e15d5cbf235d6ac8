#include "ray/adaptive_supersampling.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace rise {
namespace {

float largestDifference(const std::array<Color, 4>& corners) {
  float largest = 0.0f;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      largest = std::max(largest, maxComponent(glm::abs(corners[i] - corners[j])));
  return largest;
}

// A sample at a raster position, its other values drawn from `rng`.
SampleResult traceAlone(const TraceSample& trace, const Vec2& raster, Rng& rng,
                        TraceCounters& counters) {
  SampleValues values(rng);
  return trace(raster, values, counters, nullptr);
}

// Adaptive supersampling of one square of the image: the average of its
// corners if they agree, or else of its four quarters, each refined in turn,
// down to `levelsLeft` more subdivisions. Corners are ordered top-left,
// top-right, bottom-left, bottom-right.
class AdaptiveRefinement {
 public:
  AdaptiveRefinement(const TraceSample& trace, float threshold, Rng& rng, TraceCounters& counters)
      : trace_(trace), threshold_(threshold), rng_(rng), counters_(counters) {}

  Color refine(const Vec2& topLeft, float size, const std::array<Color, 4>& corners,
               int levelsLeft) {
    if (levelsLeft == 0 || largestDifference(corners) <= threshold_)
      return 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
    refined_ = true;
    const float half = 0.5f * size;
    const Color top = colorAt(topLeft + Vec2(half, 0.0f));
    const Color left = colorAt(topLeft + Vec2(0.0f, half));
    const Color centre = colorAt(topLeft + Vec2(half, half));
    const Color right = colorAt(topLeft + Vec2(size, half));
    const Color bottom = colorAt(topLeft + Vec2(half, size));
    const int next = levelsLeft - 1;
    return 0.25f *
           (refine(topLeft, half, {corners[0], top, left, centre}, next) +
            refine(topLeft + Vec2(half, 0.0f), half, {top, corners[1], centre, right}, next) +
            refine(topLeft + Vec2(0.0f, half), half, {left, centre, corners[2], bottom}, next) +
            refine(topLeft + Vec2(half, half), half, {centre, right, bottom, corners[3]}, next));
  }

  bool refined() const { return refined_; }

 private:
  Color colorAt(const Vec2& raster) { return traceAlone(trace_, raster, rng_, counters_).color; }

  const TraceSample& trace_;
  float threshold_;
  Rng& rng_;
  TraceCounters& counters_;
  bool refined_ = false;
};

// The subdivisions that `samples` allow: 16 samples, two levels of quarters.
int adaptiveLevels(int samples) {
  int levels = 0;
  for (int cells = 1; cells < samples; cells *= 4) ++levels;
  return levels;
}

}  // namespace

void sampleAdaptively(TileTrace& tile, const RenderSettings& settings, const TraceSample& trace) {
  const PixelRect& area = tile.area();
  TraceCounters& counters = tile.counters;
  std::vector<SampleResult> corners;
  std::vector<std::uint64_t> cornerTests;
  for (int y = area.y0; y <= area.y1; ++y) {
    for (int x = area.x0; x <= area.x1; ++x) {
      Rng rng(pixelSeed(settings.seed, x, y), 1);
      const std::uint64_t testsBefore = counters.intersections.tests;
      corners.push_back(
          traceAlone(trace, Vec2(static_cast<float>(x), static_cast<float>(y)), rng, counters));
      cornerTests.push_back(counters.intersections.tests - testsBefore);
    }
  }
  const auto corner = [&](int x, int y) {
    return static_cast<std::size_t>(y - area.y0) * (area.width() + 1) + (x - area.x0);
  };
  const int levels = adaptiveLevels(settings.sampling.samples);
  for (int y = area.y0; y < area.y1 && !tile.cancelled(); ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      Rng rng(pixelSeed(settings.seed, x, y), 2);
      const std::uint64_t testsBefore = counters.intersections.tests;
      AdaptiveRefinement refinement(trace, settings.sampling.adaptiveThreshold, rng, counters);
      const Color color =
          refinement.refine(Vec2(static_cast<float>(x), static_cast<float>(y)), 1.0f,
                            {corners[corner(x, y)].color, corners[corner(x + 1, y)].color,
                             corners[corner(x, y + 1)].color, corners[corner(x + 1, y + 1)].color},
                            levels);
      tile.addSample({x, y}, Vec2(0.5f), color);
      if (refinement.refined()) ++tile.refinedPixels;
      tile.recordBuffers({x, y}, corners[corner(x, y)],
                         cornerTests[corner(x, y)] + counters.intersections.tests - testsBefore);
    }
  }
}

}  // namespace rise
