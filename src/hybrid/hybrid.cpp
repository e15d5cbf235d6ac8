// The hybrid scan-line / ray-tracing algorithm, after M. Dreux, "A Hybrid
// Scan-Line / Ray-Tracing Algorithm" (PhD thesis, Brunel University, 1989),
// the step the original RISE report was studying when it ended, and the item
// buffer of Weghorst, Hooper and Greenberg ("Improved computational methods
// for ray tracing", ACM TOG 3(1), 1984).
//
// Most of a ray tracer's work in a simple scene is finding what each primary
// ray hits first: one search of the whole scene a pixel. A scanline pass
// answers that question for every pixel at once, far more cheaply than a
// search of every object, and rays are then spent where the scanline cannot
// answer: shadows, mirrors, glass. (A BVH whose primary rays go down it in
// packets finds the first hits for about as little as the scanline pass and
// the item tests do, less on a million triangles or with many samples a
// pixel: bench/README.md. The hybrid's lead is mostly in its shading, below,
// and on a large mesh in the parts of the BVH that its rays never reach, and
// that the BVH therefore never builds: bvh.hpp.)
//   Pass 1, visibility by scanline: the scanline algorithm (scanline.cpp),
//     sampling pixel centres where the primary rays pass, fills an item
//     buffer: the polygon seen at each pixel, and so the object under it and,
//     for a mesh, the triangle (the "face" buffer shows it).
//   Pass 2, shading by rays: each pixel's primary ray is intersected with its
//     item alone, the exact surface and not its polygon, so that a sphere is
//     still a sphere; from that hit on the recursion is Whitted's
//     (ray_tracing.cpp): shadow rays, and reflection and refraction rays
//     where the material has them, through the whole acceleration structure.
//     A pixel where the item buffer shows nothing takes the background, and
//     no ray at all. The first hits of a run of a row's pixels being known
//     before any of them is shaded, the run is shaded as a batch whose
//     shadow rays go through the structure together, a packet towards each
//     light (first_hit_batch.hpp): the same rays and colours as one pixel at
//     a time, at less cost. Whitted's recursion, one ray after another,
//     cannot gather them so.
//
// Silhouettes. Polygons are not the exact surfaces: a curved object's lie
// inside its true outline, and at any edge rounding may put a pixel centre on
// either side. Where they disagree the item buffer is wrong there, and the
// pixel falls back to a full primary ray, Whitted's own: the rule that finds
// those pixels is told in hybrid_silhouettes.cpp. Everywhere else the item
// buffer's answer is the primary ray's, to the bit.
//
// Anti-aliasing, depth of field and motion blur come from the accumulation
// passes of the visible-surface algorithms (visible_surface_renderer.hpp):
// each pass does both passes above at its own offset in the pixel, point of
// the lens and instant of the shutter interval. The accumulation passes are
// taken a few at a time: pass 1 for each, then pass 2 for all of them, a
// pixel's samples found and shaded one after another, their shadow rays in
// the same packets. A pixel's samples are nearly the same rays: the later
// ones find in the cache the boxes of the structure and the surface the
// first one fetched, as the samples of Whitted's pixel, traced one after
// another, do. Where the film keeps each sample in its pixel (the box
// filter), the group's samples go into one image of their means, not one
// image a pass: a group's passes take the image memory of one.
//
// Its steps, for a student: the item buffer filling, a scanline a step, the
// items in their materials' colours; then each band of pixels shaded, with
// the pixels that fell back and those that spawned mirror or glass rays. The
// ray tree of a chosen pixel is Whitted's, one for each accumulation pass.
//
// This file holds the algorithm and its two passes; hybrid_silhouettes.cpp
// the rule for silhouettes, hybrid_row_shading.cpp the shading along rows,
// hybrid_pass.cpp the bookkeeping of each accumulation pass (what each keeps
// and where its samples go).
#include "hybrid/hybrid.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <span>
#include <vector>

#include "core/elapsed.hpp"
#include "hybrid/hybrid_group.hpp"
#include "raster/bands.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& HybridRenderer::description() const {
  static const AlgorithmDescription description{
      .name = "hybrid",
      .summary =
          "Dreux's hybrid: what each pixel sees by scanline into an item buffer, its "
          "shading by Whitted's rays",
      .citation =
          "M. Dreux, A Hybrid Scan-Line / Ray-Tracing Algorithm, PhD thesis, Brunel University, "
          "1989; H. Weghorst, G. Hooper, D. P. Greenberg, Improved computational methods for ray "
          "tracing, ACM TOG 3(1), 1984",
      .family = Family::Hybrid,
      .buffers = {"depth", "normal", "cost", "face"},
      .options = {Option::Culling, Option::Tessellation, Option::PlaneSize, Option::Accel,
                  Option::MaxDepth},
      .effects = {Effect::Shadows, Effect::Reflection, Effect::Refraction, Effect::DepthOfField,
                  Effect::MotionBlur},
      .sameImageAs = "ray-tracing",
      .looks = {Look::Steps, Look::RayTrees},
      // Each pass is drawn whole, as the visible-surface algorithms draw it.
      .tileStatistics = TileStatistics::WholeImage};
  return description;
}

// The visible-surface algorithms' memory, and the rays of Whitted's
// recursion from every sample's first hit.
RenderNeeds HybridRenderer::needs(const Scene& scene, const RenderSettings& settings) const {
  RenderNeeds needs = visibleSurfaceNeeds(scene, settings);
  needs.rays = recursionRays(scene, settings);
  return needs;
}

namespace {

// Four passes in a group: a packet of eight shadow rays then leaves from two
// neighbouring pixels, and more passes gain little more and take memory.
// Fewer where the pixels' images of four passes would take more than a
// quarter of a gigabyte (a large image), and at least one.
int largestGroup(const RenderSettings& settings) {
  constexpr std::size_t kPasses = 4;
  constexpr std::size_t kGroupBytes = std::size_t{256} << 20;
  const std::size_t images = settings.wantsBuffer("cost") ? 2 : 1;
  const std::size_t passBytes =
      std::max<std::size_t>(1, static_cast<std::size_t>(settings.width) * settings.height *
                                   (sizeof(hybrid::Settled) + images * sizeof(Color)));
  return static_cast<int>(std::clamp<std::size_t>(kGroupBytes / passBytes, 1, kPasses));
}

}  // namespace

RenderResult HybridRenderer::render(const Scene& scene, const RenderSettings& settings,
                                    RenderObserver& observer) const {
  return renderWithRays(scene, settings, [&](const TracingContext& context) {
    HybridCounters counters;
    std::vector<hybrid::SettledPixels> settled;
    RenderResult result = renderInPassGroups(
        scene, settings, observer, largestGroup(settings),
        [&](const TessellatedScene& tessellated, std::span<const AccumulationPass> passes,
            int firstPass, PassProjections& projections, Film& film,
            RenderObserver& groupObserver) {
          return hybrid::HybridGroup(context, tessellated, settings, passes, firstPass, projections,
                                     film, groupObserver, observer.stepRecorder(), settled)
              .run(counters);
        },
        sceneTessellator(scene, settings));
    addHybridStats(result.stats, counters);
    return result;
  });
}

namespace hybrid {

// Each pass of the group with the images and records it fills; where the
// film keeps each sample in its pixel, one image of samples for them all.
HybridGroup::HybridGroup(const TracingContext& context, const TessellatedScene& tessellated,
                         const RenderSettings& settings, std::span<const AccumulationPass> passes,
                         int firstPass, PassProjections& projections, Film& film,
                         RenderObserver& observer, StepRecorder* trees,
                         std::vector<SettledPixels>& settled)
    : context_(context),
      tessellated_(tessellated),
      settings_(settings),
      projections_(projections),
      film_(film),
      observer_(observer),
      workers_(settings.threads, observer) {
  settled.resize(std::max(settled.size(), passes.size()));
  const bool shared = std::ranges::all_of(passes, [&](const AccumulationPass& pass) {
    return film.keepsEachSampleInItsPixel(pass.pixelOffset);
  });
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const PassRecording recording{i == 0 ? observer.stepRecorder() : nullptr, trees,
                                  firstPass + static_cast<int>(i)};
    const bool clearsSamples = i == 0 || !shared;
    if (clearsSamples) {
      const int sharing = shared ? static_cast<int>(passes.size()) : 1;
      sampleImages_.push_back({Image::unfilled(settings.width, settings.height), sharing,
                               1.0f / static_cast<float>(sharing)});
    }
    passes_.emplace_back(passes[i], recording, settled[i], sampleImages_.back(), clearsSamples,
                         settings);
  }
}

// Pass 1 for each pass of the group, then pass 2 for them all: the bands,
// then the outlines and the pixel whose ray tree is recorded, pass by pass.
std::vector<RenderResult> HybridGroup::run(HybridCounters& counters) {
  std::vector<Stats> stats(passes_.size());
  fillItemBuffers(stats, counters);
  const auto start = std::chrono::steady_clock::now();
  BandWork work = shadeInBands();
  work.passes.resize(passes_.size());
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    PassWork& passWork = work.passes[i];
    // A cancelled pass 2 left pixels unwritten, which the outlines may not
    // read.
    if (!workers_.cancelled()) {
      followOutlines(passes_[i], passWork);
      shadeTreePixels(passes_[i], passWork);
    }
    counters += passWork.counters;
    stats[i].add("covered_pixels", static_cast<double>(passWork.coveredPixels));
    passes_[i].images.result.stats = std::move(stats[i]);
  }
  counters.raySeconds += secondsSince(start);

  addSamplesToFilm();
  std::vector<RenderResult> results;
  for (GroupPass& pass : passes_) results.push_back(std::move(pass.images.result));
  return results;
}

// Pass 1: an item buffer for each pass, its counters into `stats`.
void HybridGroup::fillItemBuffers(std::vector<Stats>& stats, HybridCounters& counters) {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    GroupPass& pass = passes_[i];
    pass.items = &itemBuffers_.emplace_back(
        context_.scene, tessellated_, projections_.of(pass.recording.index, tessellated_),
        settings_.width, settings_.height, workers_, pass.recording.steps, stats[i]);
  }
  counters.itemBufferSeconds += secondsSince(start);
}

// Pass 2 but the outlines, band by band on the workers, each band's step
// recorded and its pixels shown as soon as it is done.
HybridGroup::BandWork HybridGroup::shadeInBands() {
  const std::vector<PixelRect> bands = makeBands(settings_.width, settings_.height);
  return workers_.sumOverTasks<BandWork>(static_cast<int>(bands.size()), [&](int task,
                                                                             BandWork& work) {
    const PixelRect& band = bands[static_cast<std::size_t>(task)];
    shadeBand(band, work);
    const GroupPass& first = passes_.front();
    if (first.recording.steps)
      first.recording.steps->record(raysStep(band, work.passes.front().counters,
                                             [&](int x, int y) { return shownOf(first, x, y); }),
                                    settings_.height + task);
    observer_.onPixelsDone(band, first.samples.means);
  });
}

void HybridGroup::shadeBand(const PixelRect& band, BandWork& work) {
  work.passes.resize(passes_.size());
  RowScratch scratch(context_);
  for (int y = band.y0; y < band.y1; ++y) findAndShadeRow(y, band.x0, band.x1, scratch, work);
}

}  // namespace hybrid

}  // namespace rise
