#include "ray/image_sampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/film.hpp"
#include "render/tiles.hpp"

namespace rise {
namespace {

// The camera samples of one pixel: n values for each dimension, every
// dimension stratified on its own (uniformly random for the random pattern)
// and shuffled, which is Cook's decorrelation. For a tracer that reads only
// the pixel dimension, the others are their centres, never generated. Kept
// across the pixels of a tile to spare an allocation per pixel.
class CameraSampleSet {
 public:
  explicit CameraSampleSet(bool withEffects) : withEffects_(withEffects) {}

  void generate(int x, int y, const PixelSampling& sampling, Rng& rng) {
    corner_ = Vec2(static_cast<float>(x), static_cast<float>(y));
    samplePositions(sampling.pattern, sampling.samples, rng, pixel_);
    if (withEffects_)
      generateEffects(sampling.samples, sampling.pattern == SamplePattern::Random, rng);
  }

  int size() const { return static_cast<int>(pixel_.size()); }
  // Where sample i lies in its pixel, from the top-left corner.
  const Vec2& offset(int i) const { return pixel_[i]; }
  CameraSample operator[](int i) const {
    if (!withEffects_) return {corner_ + pixel_[i], Vec2(0.5f), 0.5f, Vec2(0.5f), Vec2(0.5f)};
    return {corner_ + pixel_[i], lens_[i], time_[i], light_[i], gloss_[i]};
  }

 private:
  void generateEffects(int n, bool random, Rng& rng) {
    const SamplePattern spread = random ? SamplePattern::Random : SamplePattern::Jittered;
    samplePositions(spread, n, rng, lens_);
    samplePositions(spread, n, rng, light_);
    samplePositions(spread, n, rng, gloss_);
    jitteredValues(n, rng, time_);
    if (random)
      for (float& t : time_) t = rng.uniform();
    shuffle(lens_, rng);
    shuffle(light_, rng);
    shuffle(gloss_, rng);
    shuffle(time_, rng);
  }

  bool withEffects_;
  Vec2 corner_;
  std::vector<Vec2> pixel_, lens_, light_, gloss_;
  std::vector<float> time_;
};

// A camera sample at a given raster position, its other dimensions random.
CameraSample sampleAt(const Vec2& raster, Rng& rng) {
  return {raster,
          {rng.uniform(), rng.uniform()},
          rng.uniform(),
          {rng.uniform(), rng.uniform()},
          {rng.uniform(), rng.uniform()}};
}

float largestDifference(const std::array<Color, 4>& corners) {
  float largest = 0.0f;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      largest = std::max(largest, maxComponent(glm::abs(corners[i] - corners[j])));
  return largest;
}

// Whitted's adaptive supersampling of one square of the image: the average
// of its corners if they agree, or else of its four quarters, each refined in
// turn, down to `levelsLeft` more subdivisions. Corners are ordered top-left,
// top-right, bottom-left, bottom-right.
class AdaptiveRefinement {
 public:
  AdaptiveRefinement(const SampleTracer& tracer, float threshold, Rng& rng, TraceCounters& counters)
      : tracer_(tracer), threshold_(threshold), rng_(rng), counters_(counters) {}

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
  Color colorAt(const Vec2& raster) {
    return tracer_.trace(sampleAt(raster, rng_), rng_, counters_).color;
  }

  const SampleTracer& tracer_;
  float threshold_;
  Rng& rng_;
  TraceCounters& counters_;
  bool refined_ = false;
};

int adaptiveLevels(int samples) {
  int levels = 0;
  for (int cells = 1; cells < samples; cells *= 4) ++levels;
  return levels;
}

// Everything one tile produced, combined in tile order afterwards.
struct TileOutput {
  TraceCounters counters;
  std::uint64_t refinedPixels = 0;
};

class ImageSampler {
 public:
  ImageSampler(const RenderSettings& settings, const SampleTracer& tracer, RenderResult& result)
      : settings_(settings),
        tracer_(tracer),
        depth_(result.buffers["depth"] = Image(settings.width, settings.height, Color(kInfinity))),
        normal_(result.buffers["normal"] = Image(settings.width, settings.height)),
        cost_(result.buffers["cost"] = Image(settings.width, settings.height)) {}

  void renderTile(const Tile& tile, FilmTile& film, TileOutput& output) const {
    if (settings_.sampling.pattern == SamplePattern::Adaptive)
      renderAdaptiveTile(tile, film, output);
    else
      renderStratifiedTile(tile, film, output);
  }

 private:
  void record(int x, int y, const SampleResult& sample, std::uint64_t tests) const {
    depth_.at(x, y) = Color(sample.depth);
    normal_.at(x, y) = sample.normal;
    cost_.at(x, y) = Color(static_cast<float>(tests));
  }

  void renderStratifiedTile(const Tile& tile, FilmTile& film, TileOutput& output) const {
    TraceCounters& counters = output.counters;
    CameraSampleSet samples(tracer_.usesEffectSamples());
    for (int y = tile.y0; y < tile.y1; ++y) {
      for (int x = tile.x0; x < tile.x1; ++x) {
        Rng rng(pixelSeed(settings_.seed, x, y));
        samples.generate(x, y, settings_.sampling, rng);
        const std::uint64_t testsBefore = counters.intersections.tests;
        SampleResult first;
        for (int i = 0; i < samples.size(); ++i) {
          const SampleResult result = tracer_.trace(samples[i], rng, counters);
          film.addSample({x, y}, samples.offset(i), result.color);
          if (i == 0) first = result;
        }
        record(x, y, first, counters.intersections.tests - testsBefore);
      }
    }
  }

  // The tile's pixel corners are traced once each, shared by the pixels
  // around them; each pixel then refines its own square.
  void renderAdaptiveTile(const Tile& tile, FilmTile& film, TileOutput& output) const {
    TraceCounters& counters = output.counters;
    const int columns = tile.x1 - tile.x0 + 1;
    std::vector<SampleResult> corners;
    std::vector<std::uint64_t> cornerTests;
    for (int y = tile.y0; y <= tile.y1; ++y) {
      for (int x = tile.x0; x <= tile.x1; ++x) {
        Rng rng(pixelSeed(settings_.seed, x, y), 1);
        const std::uint64_t testsBefore = counters.intersections.tests;
        const Vec2 raster(static_cast<float>(x), static_cast<float>(y));
        corners.push_back(tracer_.trace(sampleAt(raster, rng), rng, counters));
        cornerTests.push_back(counters.intersections.tests - testsBefore);
      }
    }
    const auto corner = [&](int x, int y) {
      return static_cast<std::size_t>(y - tile.y0) * columns + (x - tile.x0);
    };
    const int levels = adaptiveLevels(settings_.sampling.samples);
    for (int y = tile.y0; y < tile.y1; ++y) {
      for (int x = tile.x0; x < tile.x1; ++x) {
        Rng rng(pixelSeed(settings_.seed, x, y), 2);
        const std::uint64_t testsBefore = counters.intersections.tests;
        AdaptiveRefinement refinement(tracer_, settings_.sampling.adaptiveThreshold, rng, counters);
        const Color color = refinement.refine(
            Vec2(static_cast<float>(x), static_cast<float>(y)), 1.0f,
            {corners[corner(x, y)].color, corners[corner(x + 1, y)].color,
             corners[corner(x, y + 1)].color, corners[corner(x + 1, y + 1)].color},
            levels);
        film.addSample({x, y}, Vec2(0.5f), color);
        if (refinement.refined()) ++output.refinedPixels;
        record(x, y, corners[corner(x, y)],
               cornerTests[corner(x, y)] + counters.intersections.tests - testsBefore);
      }
    }
  }

  const RenderSettings& settings_;
  const SampleTracer& tracer_;
  Image& depth_;
  Image& normal_;
  Image& cost_;
};

}  // namespace

RenderResult renderBySampling(const RenderSettings& settings, RenderObserver& observer,
                              const SampleTracer& tracer) {
  RenderResult result;
  const ImageSampler sampler(settings, tracer, result);
  Film film(settings.width, settings.height, settings.sampling.filter);

  const std::vector<Tile> tiles = makeTiles(settings.width, settings.height);
  std::vector<FilmTile> filmTiles;
  filmTiles.reserve(tiles.size());
  for (const Tile& tile : tiles) filmTiles.push_back(film.tileFor(tile));
  std::vector<TileOutput> outputs(tiles.size());
  renderTiles(tiles, settings.threads, observer, [&](const Tile& tile) {
    sampler.renderTile(tile, filmTiles[tile.index], outputs[tile.index]);
  });

  TileOutput total;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    film.merge(filmTiles[i]);
    total.counters += outputs[i].counters;
    total.refinedPixels += outputs[i].refinedPixels;
  }
  result.image = film.resolve();
  total.counters.addTo(result.stats);
  result.stats.add("samples_per_pixel", settings.sampling.samples);
  if (settings.sampling.pattern == SamplePattern::Adaptive)
    result.stats.add("adaptive_refined_pixels", static_cast<double>(total.refinedPixels));
  return result;
}

}  // namespace rise
