// What the ray tracers share around their algorithms: the image is cut into
// tiles that the workers trace apart; each sample a pixel takes is added to
// the film, where the reconstruction filter weighs it (render/film.hpp), and
// what its primary ray hit to the auxiliary buffers. Which samples a pixel
// takes and how each is traced is each algorithm's own: see ray_tracer.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "ray/trace_counters.hpp"
#include "render/film.hpp"
#include "render/renderer.hpp"

namespace rise {

// What tracing one sample found: its colour, and for the auxiliary buffers
// what the primary ray hit.
struct SampleResult {
  Color color;
  float depth = kInfinity;
  Vec3 normal{0.0f};
};

// A tile being traced: where its samples go and what they cost.
class TileTrace {
 public:
  TileTrace(const PixelRect& area, FilmTile film, RenderResult& buffers, RenderObserver& observer);

  const PixelRect& area() const { return area_; }
  // Where the ray trees of a pixel are recorded, or nullptr.
  StepRecorder* steps() const { return steps_; }
  // Asked before each row of the tile: a tile of many samples takes a
  // noticeable time, and a cancelled render must stop at once.
  bool cancelled() const { return observer_.cancelled(); }

  // A sample taken in `pixel` at `offset` from its top-left corner.
  void addSample(const glm::ivec2& pixel, const Vec2& offset, const Color& color) {
    film_.addSample(pixel, offset, color);
  }
  // The pixel's auxiliary buffers: what `shown` hit, and the intersection
  // tests the pixel cost.
  void recordBuffers(const glm::ivec2& pixel, const SampleResult& shown, std::uint64_t tests);
  // Whether the render wants any of them.
  bool recordsBuffers() const { return depth_ || normal_ || cost_; }

  FilmTile& film() { return film_; }

  TraceCounters counters;
  std::uint64_t refinedPixels = 0;  // by adaptive supersampling

 private:
  PixelRect area_;
  FilmTile film_;
  const RenderObserver& observer_;
  StepRecorder* steps_;
  Image* depth_;  // or none, where not wanted
  Image* normal_;
  Image* cost_;
};

// Renders the image by calling traceTile for every tile, on the workers, and
// returns it with the auxiliary buffers and the counters summed in tile order.
// Each tile is a step of the render, for whoever records them.
RenderResult traceImage(const RenderSettings& settings, RenderObserver& observer,
                        const std::function<void(TileTrace&)>& traceTile);

// Traces sample i of the pixel, at `offset` in it, recording its rays as a
// ray tree of the tile's recorder.
template <typename Trace>
SampleResult traceRecorded(TileTrace& tile, const glm::ivec2& pixel, int i, const Vec2& offset,
                           Rng& rng, const Trace& trace) {
  RayTree tree;
  tree.pixel = pixel;
  tree.sample = i;
  tree.raster = Vec2(pixel) + offset;
  const SampleResult sample = trace(pixel, i, rng, tile.counters, &tree);
  tile.steps()->recordTree(std::move(tree));
  return sample;
}

// The common pixel loop: for each pixel of the tile, a generator seeded by
// the pixel alone (so that the image does not depend on which thread traced
// it); place(pixel, rng) puts the pixel's samples and returns their offsets
// in it; trace(pixel, i, rng, counters, tree) traces sample i, recording its
// rays in `tree` unless that is null (a tree is made only for the pixel
// recorded). Every sample goes to the film, the first to the buffers, if
// any is wanted: copying a sample just after it was made field by field
// waits for those writes.
template <typename Place, typename Trace>
void tracePixels(TileTrace& tile, std::uint64_t seed, const Place& place, const Trace& trace) {
  const PixelRect& area = tile.area();
  StepRecorder* const steps = tile.steps();
  const bool buffers = tile.recordsBuffers();
  for (int y = area.y0; y < area.y1 && !tile.cancelled(); ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const glm::ivec2 pixel(x, y);
      Rng rng(pixelSeed(seed, x, y));
      const std::vector<Vec2>& offsets = place(pixel, rng);
      const std::uint64_t testsBefore = tile.counters.intersections.tests;
      SampleResult first;
      const bool recording = steps && steps->wantsTreeOf(pixel);
      for (int i = 0; i < static_cast<int>(offsets.size()); ++i) {
        const Vec2& offset = offsets[static_cast<std::size_t>(i)];
        const SampleResult sample = recording ? traceRecorded(tile, pixel, i, offset, rng, trace)
                                              : trace(pixel, i, rng, tile.counters, nullptr);
        tile.addSample(pixel, offset, sample.color);
        if (i == 0 && buffers) first = sample;
      }
      if (buffers)
        tile.recordBuffers(pixel, first, tile.counters.intersections.tests - testsBefore);
    }
  }
}

}  // namespace rise
