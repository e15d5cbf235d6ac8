// The hybrid scan-line / ray-tracing algorithm, after M. Dreux, "A Hybrid
// Scan-Line / Ray-Tracing Algorithm" (PhD thesis, Brunel University, 1989),
// the step the original RISE report was studying when it ended, and the item
// buffer of Weghorst, Hooper and Greenberg ("Improved computational methods
// for ray tracing", ACM TOG 3(1), 1984).
//
// Most of a ray tracer's work in a simple scene is finding what each primary
// ray hits first: one search of the whole scene a pixel. A scanline pass
// answers that question for every pixel at once, far more cheaply, and rays
// are then spent where the scanline cannot answer: shadows, mirrors, glass.
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
//     no ray at all. All of a row's first hits being known before any is
//     shaded, a run of neighbours is shaded as a batch whose shadow rays go
//     through the structure together, a packet towards each light
//     (first_hit_batch.hpp): the same rays and colours as one pixel at a
//     time, at less cost. Whitted's recursion, one ray after another, cannot
//     gather them so.
//
// Silhouettes. Polygons are not the exact surfaces: a curved object's lie
// inside its true outline, and at any edge rounding may put a pixel centre on
// either side. Where they disagree the item buffer is wrong there, and the
// pixel falls back to a full primary ray, Whitted's own. The rule:
//   outside  the pixel's ray misses its own item's exact surface: its polygon
//            reaches past the true outline;
//   inside   the item seen at a neighbouring pixel (left, right, above or
//            below) meets the pixel's ray nearer than its own item does, or
//            where the item buffer shows nothing: that item's true outline
//            reaches past its polygons. The neighbours of such a pixel are
//            tested against the same item in turn, so that the test follows
//            the outline as far out as it reaches.
// Everywhere else the item buffer's answer is the primary ray's, to the bit.
// (A sliver of an exact surface narrower than a pixel, where none of its
// polygons is seen nearby, escapes the rule: a few pixels at most.)
//
// Anti-aliasing, depth of field and motion blur come from the accumulation
// passes of the visible-surface algorithms (visible_surface_renderer.hpp):
// each pass does both passes above at its own offset in the pixel, point of
// the lens and instant of the shutter interval.
//
// Its steps, for a student: the item buffer filling, a scanline a step, the
// items in their materials' colours; then each band of pixels shaded, with
// the pixels that fell back and those that spawned mirror or glass rays. The
// ray tree of a chosen pixel is Whitted's, one for each accumulation pass.
#include "hybrid/hybrid.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>
#include <vector>

#include "hybrid/hybrid_counters.hpp"
#include "hybrid/item_buffer.hpp"
#include "raster/bands.hpp"
#include "raster/visible_surface_renderer.hpp"
#include "ray/distributed_ray_tracing.hpp"
#include "ray/first_hit_batch.hpp"
#include "ray/ray_tracing.hpp"

namespace rise {

const AlgorithmDescription& HybridRenderer::description() const {
  static const AlgorithmDescription description{
      "hybrid",
      "Dreux's hybrid: what each pixel sees by scanline into an item buffer, its shading by "
      "Whitted's rays",
      "M. Dreux, A Hybrid Scan-Line / Ray-Tracing Algorithm, PhD thesis, Brunel University, "
      "1989; H. Weghorst, G. Hooper, D. P. Greenberg, Improved computational methods for ray "
      "tracing, ACM TOG 3(1), 1984",
      Family::Hybrid,
      {"depth", "normal", "cost", "face"},
      {Option::Culling, Option::Tessellation, Option::PlaneSize, Option::Accel, Option::MaxDepth},
      {Effect::Shadows, Effect::Reflection, Effect::Refraction, Effect::DepthOfField,
       Effect::MotionBlur},
      "ray-tracing"};
  return description;
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// An image of the size and, all of zeros, the buffers the settings want: the
// "cost" buffer and, with `whatWasHit`, those of what the primary rays hit,
// which the accumulation keeps of its first pass alone
// (visible_surface_renderer.hpp).
RenderResult blankResult(const RenderSettings& settings, bool whatWasHit) {
  RenderResult result{Image(settings.width, settings.height), {}, {}};
  if (settings.wantsBuffer("cost"))
    result.buffers.emplace("cost", Image(settings.width, settings.height));
  if (whatWasHit)
    for (const char* name : {"depth", "normal", "face"})
      if (settings.wantsBuffer(name))
        result.buffers.emplace(name, Image(settings.width, settings.height));
  return result;
}

// Where one accumulation pass reports: its steps (the first pass's only) and
// the ray trees of the chosen pixel, as sample `index` of the pixel.
struct PassRecording {
  StepRecorder* steps;
  StepRecorder* trees;
  int index;
};

// What pass 2 knows of a pixel.
struct Pixel {
  Ray ray;  // its primary ray, made once for all that tests and shades it
  Item item;
  Hit hit;  // the ray's hit on its item's exact surface
  Verdict verdict = Verdict::FromItemBuffer;
  bool mirrorOrGlass = false;  // its shading spawned reflected or refracted rays
  std::uint32_t tests = 0;     // intersection tests made for it, for the "cost" buffer
};

// Both passes of one accumulation pass.
class HybridPass {
 public:
  HybridPass(const TracingContext& context, const TessellatedScene& tessellated,
             const RenderSettings& settings, const AccumulationPass& pass, RenderObserver& observer,
             const PassRecording& recording, std::vector<Pixel>& pixels)
      : context_(context),
        tessellated_(tessellated),
        settings_(settings),
        pass_(pass),
        recording_(recording),
        observer_(observer),
        workers_(settings.threads, observer),
        view_(context.scene.camera, settings.width, settings.height),
        projection_(view_, pass.pixelOffset, pass.lens),
        pixels_(pixels) {
    pixels_.resize(static_cast<std::size_t>(settings.width) * settings.height);
  }

  RenderResult run(HybridCounters& counters) {
    Stats stats;
    auto start = std::chrono::steady_clock::now();
    items_.emplace(context_.scene, tessellated_, projection_, settings_.backfaceCulling, workers_,
                   recording_.steps, stats);
    counters.itemBufferSeconds += secondsSince(start);

    start = std::chrono::steady_clock::now();
    BandWork found = inBands<BandWork>(
        [&](int y, int x0, int x1, BandWork& band) {
          for (int x = x0; x < x1; ++x) findHit(x, y, band);
        },
        [](const PixelRect&, int, const BandWork&) {});
    counters += found.counters;
    followOutlines(std::move(found.seeds), counters);
    Images images(settings_, recording_.index == 0);
    counters += inBands<HybridCounters>(
        [&](int y, int x0, int x1, HybridCounters& band) { shadeRow(y, x0, x1, images, band); },
        [&](const PixelRect& band, int task, const HybridCounters& bandCounters) {
          if (recording_.steps)
            recording_.steps->record(
                raysStep(band, bandCounters,
                         [&](int x, int y) {
                           const Pixel& pixel = at(x, y);
                           return RayPassPixel{pixel.verdict, pixel.mirrorOrGlass};
                         }),
                settings_.height + task);
          observer_.onPixelsDone(band, images.image);
        });
    counters.raySeconds += secondsSince(start);

    stats.add("covered_pixels", static_cast<double>(found.coveredPixels));
    images.result.stats = std::move(stats);
    return std::move(images.result);
  }

 private:
  // A pixel that fell back because `item` covers it: its neighbours are
  // tested against that item in turn.
  struct Seed {
    int x, y;
    Item item;
  };
  // What a band of the first sweep of pass 2 found, its seeds in order.
  struct BandWork {
    HybridCounters counters;
    std::vector<Seed> seeds;
    std::uint64_t coveredPixels = 0;  // those where the item buffer shows an object

    BandWork& operator+=(const BandWork& other) {
      counters += other.counters;
      coveredPixels += other.coveredPixels;
      seeds.insert(seeds.end(), other.seeds.begin(), other.seeds.end());
      return *this;
    }
  };

  Pixel& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * settings_.width + x]; }
  const Pixel& at(int x, int y) const {
    return pixels_[static_cast<std::size_t>(y) * settings_.width + x];
  }

  // Calls visitRow(y, x0, x1, part) for every row of every band, band by
  // band on the workers, each band with a part of its own, then done(band,
  // its number, part); returns the parts summed in order.
  template <typename Part, typename VisitRow, typename Done>
  Part inBands(const VisitRow& visitRow, const Done& done) {
    const std::vector<PixelRect> bands = makeBands(settings_.width, settings_.height);
    return workers_.sumOverTasks<Part>(static_cast<int>(bands.size()), [&](int task, Part& part) {
      const PixelRect& band = bands[static_cast<std::size_t>(task)];
      for (int y = band.y0; y < band.y1; ++y) visitRow(y, band.x0, band.x1, part);
      done(band, task, part);
    });
  }

  template <typename Visit>
  void forEachNeighbour(int x, int y, const Visit& visit) const {
    if (x > 0) visit(x - 1, y);
    if (x + 1 < settings_.width) visit(x + 1, y);
    if (y > 0) visit(x, y - 1);
    if (y + 1 < settings_.height) visit(x, y + 1);
  }

  // The primary ray of the pixel in this pass: through its sample position,
  // from its point of the lens, at its instant.
  Ray rayAt(int x, int y) const {
    Ray ray = thinLensRay(
        view_, Vec2(static_cast<float>(x), static_cast<float>(y)) + pass_.pixelOffset, pass_.lens);
    ray.time = pass_.time;
    return ray;
  }

  // The nearest hit of the pixel's ray on the item's exact surface alone.
  bool intersect(const Item& item, const Ray& ray, Pixel& pixel, Hit& hit,
                 HybridCounters& counters) {
    const std::uint64_t before = counters.traced.intersections.tests;
    const bool found =
        context_.scene.shapes[static_cast<std::size_t>(item.shape)]->intersectPrimitive(
            item.primitive, ray, 0.0f, hit, counters.traced.intersections);
    const std::uint64_t tests = counters.traced.intersections.tests - before;
    counters.counts[kItemTests] += tests;
    pixel.tests += static_cast<std::uint32_t>(tests);
    return found;
  }

  // Whether `item` meets the pixel's ray before the pixel's own item does
  // (at the same distance, the one the structures would pick: the first in
  // the scene's order).
  bool coversNearer(const Item& item, const Ray& ray, Pixel& pixel, HybridCounters& counters) {
    Hit hit;
    return intersect(item, ray, pixel, hit, counters) &&
           std::tie(hit.t, item) < std::tie(pixel.hit.t, pixel.item);
  }

  void fallBack(Pixel& pixel) {
    if (pixel.verdict == Verdict::FromItemBuffer) pixel.verdict = Verdict::Inside;
  }

  // Pass 2 begins: the pixel's ray against its own item's exact surface, then
  // against each other item seen beside it; those that cover it nearer are
  // the seeds of followOutlines.
  void findHit(int x, int y, BandWork& band) {
    Pixel& pixel = at(x, y);
    const int face = items_->faceAt(x, y);
    pixel = Pixel{};  // what the last accumulation pass left goes
    pixel.ray = rayAt(x, y);
    pixel.item = items_->itemOf(face);
    band.coveredPixels += pixel.item.shape >= 0 ? 1 : 0;
    if (pixel.item.shape >= 0 && !intersect(pixel.item, pixel.ray, pixel, pixel.hit, band.counters))
      pixel.verdict = Verdict::Outside;
    std::array<Item, 4> tested;
    int count = 0;
    forEachNeighbour(x, y, [&](int nx, int ny) {
      const int besideFace = items_->faceAt(nx, ny);
      if (besideFace == face || besideFace < 0) return;
      const Item item = items_->itemOf(besideFace);
      const auto end = tested.begin() + count;
      if (item == pixel.item || std::find(tested.begin(), end, item) != end) return;
      tested[static_cast<std::size_t>(count++)] = item;
      if (!coversNearer(item, pixel.ray, pixel, band.counters)) return;
      fallBack(pixel);
      band.seeds.push_back({x, y, item});
    });
  }

  // From each seed outwards, while the item keeps covering the pixels it
  // reaches: the true outline beyond the polygons. Seldom more than a pixel
  // or two, so done on one thread.
  void followOutlines(std::vector<Seed> seeds, HybridCounters& counters) {
    std::set<std::tuple<int, int, Item>> tested;
    for (const Seed& seed : seeds) tested.insert({seed.x, seed.y, seed.item});
    std::deque<Seed> pending(seeds.begin(), seeds.end());
    while (!pending.empty()) {
      const Seed seed = pending.front();
      pending.pop_front();
      forEachNeighbour(seed.x, seed.y, [&](int x, int y) {
        Pixel& pixel = at(x, y);
        if (pixel.item == seed.item || !tested.insert({x, y, seed.item}).second) return;
        if (!coversNearer(seed.item, pixel.ray, pixel, counters)) return;
        fallBack(pixel);
        pending.push_back({x, y, seed.item});
      });
    }
  }

  // The pass's image and buffers, filled pixel by pixel.
  struct Images {
    Images(const RenderSettings& settings, bool whatWasHit)
        : result{blankResult(settings, whatWasHit)} {}

    RenderResult result;
    Image& image = result.image;
    Image* cost = result.buffer("cost");  // or none, where not wanted
    // None but in the first pass, and there only those wanted.
    Image* depth = result.buffer("depth");
    Image* normal = result.buffer("normal");
    Image* face = result.buffer("face");
  };

  // A row's pixels, a run of neighbours at a time. The pixels whose first
  // hits the item buffer gave are shaded as a batch (first_hit_batch.hpp),
  // their shadow rays traced together; the others, and the pixel whose ray
  // tree is recorded, are shaded whole at once.
  void shadeRow(int y, int x0, int x1, Images& images, HybridCounters& counters) {
    constexpr int kRun = 64;
    FirstHitBatch batch(context_);
    std::vector<int> batched;  // the x of each of the batch's pixels
    SingleRayChoices whitted;
    for (int start = x0; start < x1; start += kRun) {
      batch.clear();
      batched.clear();
      for (int x = start; x < std::min(x1, start + kRun); ++x) {
        if (!shadedInBatch(x, y)) {
          shade(x, y, images, counters);
          continue;
        }
        ++counters.counts[kFromItemBuffer];
        batch.add(at(x, y).ray, at(x, y).hit, whitted, counters.traced);
        batched.push_back(x);
      }
      batch.traceShadowRays(counters.traced);
      for (std::size_t i = 0; i < batch.size(); ++i) {
        const int x = batched[i];
        at(x, y).tests += static_cast<std::uint32_t>(batch.shadowRayTests(i));
        const RaysSoFar before(counters.traced);
        const SampleResult sample = batch.finish(i, whitted, counters.traced);
        record(x, y, sample, batch.sentShadowRays(i), before, images, counters);
      }
    }
  }

  bool shadedInBatch(int x, int y) const {
    const Pixel& pixel = at(x, y);
    return pixel.verdict == Verdict::FromItemBuffer && pixel.item.shape >= 0 &&
           !(recording_.trees && recording_.trees->wantsTreeOf({x, y}));
  }

  // The counts of the rays traced so far, to tell what a pixel's shading
  // spawned.
  struct RaysSoFar {
    explicit RaysSoFar(const TraceCounters& traced)
        : shadow(traced.shadowRays),
          mirrorOrGlass(traced.reflectionRays + traced.refractionRays),
          tests(traced.intersections.tests) {}

    std::uint64_t shadow, mirrorOrGlass, tests;
  };

  // Whitted's Shade from the item's hit, or his whole primary ray where the
  // pixel fell back.
  void shade(int x, int y, Images& images, HybridCounters& counters) {
    Pixel& pixel = at(x, y);
    TraceCounters& traced = counters.traced;
    const RaysSoFar before(traced);
    SingleRayChoices whitted;
    // A tree is made only for the pixel recorded.
    std::optional<RayTree> tree;
    if (recording_.trees && recording_.trees->wantsTreeOf({x, y})) {
      tree.emplace();
      tree->pixel = {x, y};
      tree->sample = recording_.index;
      tree->raster = Vec2(x, y) + pass_.pixelOffset;
    }
    RayTree* const treeHere = tree ? &*tree : nullptr;
    SampleResult sample;
    if (pixel.verdict != Verdict::FromItemBuffer) {
      ++counters.counts[pixel.verdict == Verdict::Outside ? kOutside : kInside];
      sample = tracePrimary(context_, pixel.ray, whitted, traced, treeHere);
    } else {
      ++counters.counts[kFromItemBuffer];
      const Hit* hit = pixel.item.shape >= 0 ? &pixel.hit : nullptr;
      sample = shadeFirstHit(context_, pixel.ray, hit, whitted, traced, treeHere);
    }
    if (tree) recording_.trees->recordTree(std::move(*tree));
    record(x, y, sample, traced.shadowRays > before.shadow, before, images, counters);
  }

  // A pixel's sample, into the pass's images, and what its shading spawned
  // since `before`, into the counters.
  void record(int x, int y, const SampleResult& sample, bool spawnedShadowRays,
              const RaysSoFar& before, Images& images, HybridCounters& counters) {
    Pixel& pixel = at(x, y);
    const TraceCounters& traced = counters.traced;
    pixel.mirrorOrGlass = traced.reflectionRays + traced.refractionRays > before.mirrorOrGlass;
    counters.counts[kSpawning] += spawnedShadowRays || pixel.mirrorOrGlass;
    counters.counts[kMirrorOrGlass] += pixel.mirrorOrGlass;
    pixel.tests += static_cast<std::uint32_t>(traced.intersections.tests - before.tests);

    images.image.at(x, y) = sample.color;
    if (images.cost) images.cost->at(x, y) = Color(static_cast<float>(pixel.tests));
    if (images.depth) images.depth->at(x, y) = Color(sample.depth);
    if (images.normal) images.normal->at(x, y) = sample.normal;
    if (images.face) images.face->at(x, y) = Color(static_cast<float>(items_->sceneFaceAt(x, y)));
  }

  const TracingContext& context_;
  const TessellatedScene& tessellated_;
  const RenderSettings& settings_;
  const AccumulationPass& pass_;
  const PassRecording recording_;
  RenderObserver& observer_;
  const Workers workers_;
  const ViewFrame view_;
  const ViewProjection projection_;
  std::optional<ItemBuffer> items_;
  std::vector<Pixel>& pixels_;  // the render's, kept from pass to pass
};

}  // namespace

RenderResult HybridRenderer::render(const Scene& scene, const RenderSettings& settings,
                                    RenderObserver& observer) const {
  const SceneIntersector intersector(scene, settings.accel, settings.threads);
  const TracingContext context{scene, intersector, settings.maxDepth};
  HybridCounters counters;
  int passes = 0;
  std::vector<Pixel> pixels;
  RenderResult result = renderInPasses(
      scene, settings, observer,
      [&](const TessellatedScene& tessellated, const AccumulationPass& pass,
          RenderObserver& passObserver) {
        const PassRecording recording{passObserver.stepRecorder(), observer.stepRecorder(),
                                      passes++};
        return HybridPass(context, tessellated, settings, pass, passObserver, recording, pixels)
            .run(counters);
      });
  addHybridStats(result.stats, counters);
  intersector.addBuildStats(result.stats);
  return result;
}

}  // namespace rise
