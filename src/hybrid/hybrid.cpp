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
// pixel falls back to a full primary ray, Whitted's own. The rule:
//   outside  the pixel's ray misses its own item's exact surface: its polygon
//            reaches past the true outline;
//   inside   the item seen at a neighbouring pixel (left, right, above or
//            below) meets the pixel's ray nearer than its own item does, or
//            where the item buffer shows nothing: that item's true outline
//            reaches past its polygons. The neighbours of such a pixel are
//            tested against the same item in turn, so that the test follows
//            the outline as far out as it reaches.
// A pixel's own tests need only the item buffer, so each pixel is tested and
// shaded at once, a run of a row at a time, and nothing of it is kept in
// memory the size of the image but what its steps show. The outlines are
// followed once every row is shaded; the pixels they reach beyond the
// neighbours of their polygons (few, but a band of them around a coarsely
// cut sphere) are shaded again, by full primary rays, their first samples
// shaded once more as they were and taken back out of the image.
// Everywhere else the item buffer's answer is the primary ray's, to the bit.
// (A sliver of an exact surface narrower than a pixel, where none of its
// polygons is seen nearby, escapes the rule: a few pixels at most.)
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
#include "hybrid/hybrid.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <set>
#include <span>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/left_unfilled.hpp"
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

// The buffers the settings want, of the image's size: the "cost" buffer and,
// with `whatWasHit`, those of what the primary rays hit, which the
// accumulation keeps of its first pass alone (visible_surface_renderer.hpp).
// All are left unfilled: pass 2 writes every pixel of each, on the workers.
// The image itself is the film's (SampleImage).
RenderResult blankResult(const RenderSettings& settings, bool whatWasHit) {
  const auto unfilled = [&] { return Image::unfilled(settings.width, settings.height); };
  RenderResult result;
  if (settings.wantsBuffer("cost")) result.buffers.emplace("cost", unfilled());
  if (whatWasHit)
    for (const char* name : {"depth", "normal", "face"})
      if (settings.wantsBuffer(name)) result.buffers.emplace(name, unfilled());
  return result;
}

// Where one accumulation pass reports: its steps (the first pass's only) and
// the ray trees of the chosen pixel, as sample `index` of the pixel.
struct PassRecording {
  StepRecorder* steps;
  StepRecorder* trees;
  int index;
};

// A pixel's primary ray and the first hit the item buffer and the item tests
// found for it, from the moment they are found to its shading a few dozen
// pixels later, and never written to memory of the image's size; and whether
// the pixel falls back, told to memory (Settled) once it is shaded.
struct FoundHit {
  Ray ray;
  Item item;  // the item buffer's
  Hit hit;    // on the item's exact surface: its shape none where the item buffer shows nothing
  Verdict verdict = Verdict::FromItemBuffer;
};

// What pass 2 settled of each pixel of a pass, for the pass's steps and for
// an outline found after the pixel was shaded, which must know what it takes
// back: a byte a pixel. Left unfilled: the workers write each pixel's, so
// that its memory is first touched on all of them and not on one.
struct Settled {
  Verdict verdict : 2 = Verdict::FromItemBuffer;
  bool mirrorOrGlass : 1 = false;  // its shading spawned reflected or refracted rays
  bool spawnedRays : 1 = false;    // ... or any rays
};
static_assert(sizeof(Settled) == 1);
using SettledPixels = UnfilledVector<Settled>;

// Where the samples of one or more passes of a group go: at each pixel their
// mean, to be added to the film. Where the film keeps each sample in its
// pixel (the box filter), all the group's passes share one, and their
// samples take the memory of one image rather than one each; otherwise each
// pass has its own, added at its offset. Left unfilled: the first of its
// passes clears each pixel as it comes to it.
struct SampleImage {
  Image means;
  int passes;
  float weight;  // of each sample: 1 / passes
};

// The pass's buffers, filled pixel by pixel.
struct Images {
  Images(const RenderSettings& settings, bool whatWasHit)
      : result{blankResult(settings, whatWasHit)} {}
  Images(const Images&) = delete;  // the pointers are into its own result

  RenderResult result;
  Image* cost = result.buffer("cost");  // or none, where not wanted
  // None but in the first pass, and there only those wanted.
  Image* depth = result.buffer("depth");
  Image* normal = result.buffer("normal");
  Image* face = result.buffer("face");
};

// One pass of a group: where its rays go, where it reports, what pass 2
// settled of each pixel, where its samples go and the buffers its shading
// fills.
struct GroupPass {
  GroupPass(const AccumulationPass& pass, const PassRecording& recording, SettledPixels& settled,
            SampleImage& samples, bool clearsSamples, const RenderSettings& settings)
      : pass(pass),
        recording(recording),
        settled(settled),
        samples(samples),
        clearsSamples(clearsSamples),
        images(settings, recording.index == 0) {
    settled.resize(static_cast<std::size_t>(settings.width) * settings.height);
  }

  const AccumulationPass& pass;
  const PassRecording recording;
  SettledPixels& settled;  // the render's, kept from group to group
  SampleImage& samples;
  const bool clearsSamples;  // the first of the passes that share them
  Images images;
  const ItemBuffer* items = nullptr;  // once pass 1 has filled it
};

// Both passes of a group of accumulation passes: pass 1 for each, then pass
// 2 for them all, a pixel's samples one after another.
class HybridGroup {
 public:
  HybridGroup(const TracingContext& context, const TessellatedScene& tessellated,
              const RenderSettings& settings, std::span<const AccumulationPass> passes,
              int firstPass, PassProjections& projections, Film& film, RenderObserver& observer,
              StepRecorder* trees, std::vector<SettledPixels>& settled)
      : context_(context),
        tessellated_(tessellated),
        settings_(settings),
        projections_(projections),
        film_(film),
        observer_(observer),
        workers_(settings.threads, observer),
        view_(context.scene.camera, settings.width, settings.height) {
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

  std::vector<RenderResult> run(HybridCounters& counters) {
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

 private:
  // A pixel that fell back because `item` covers it: its neighbours are
  // tested against that item in turn.
  struct Seed {
    int x, y;
    Item item;
  };
  // The pixel whose ray tree is recorded, left to be shaded once the
  // outlines are followed: its tree is then the one of its final shading.
  struct TreePixel {
    int x, y;
    FoundHit found;
  };
  // What pass 2 did in a pass, its seeds in order.
  struct PassWork {
    HybridCounters counters;
    std::vector<Seed> seeds;
    std::vector<TreePixel> treePixels;
    std::uint64_t coveredPixels = 0;  // those where the item buffer shows an object

    PassWork& operator+=(const PassWork& other) {
      counters += other.counters;
      coveredPixels += other.coveredPixels;
      seeds.insert(seeds.end(), other.seeds.begin(), other.seeds.end());
      treePixels.insert(treePixels.end(), other.treePixels.begin(), other.treePixels.end());
      return *this;
    }
  };
  // What it did in each pass of the group.
  struct BandWork {
    std::vector<PassWork> passes;

    BandWork& operator+=(const BandWork& other) {
      passes.resize(std::max(passes.size(), other.passes.size()));
      for (std::size_t i = 0; i < other.passes.size(); ++i) passes[i] += other.passes[i];
      return *this;
    }
  };

  Item itemAt(const GroupPass& pass, int x, int y) const { return pass.items->itemAt(x, y); }
  Settled& settledAt(const GroupPass& pass, int x, int y) const {
    return pass.settled[static_cast<std::size_t>(y) * settings_.width + x];
  }
  RayPassPixel shownOf(const GroupPass& pass, int x, int y) const {
    const Settled& pixel = settledAt(pass, x, y);
    return {pixel.verdict, pixel.mirrorOrGlass};
  }
  bool isTreePixel(const GroupPass& pass, int x, int y) const {
    return pass.recording.trees && pass.recording.trees->wantsTreeOf({x, y});
  }
  // A pixel shaded after its band, to the observer, where it changed the
  // image it is shown: the first pass's samples, and those that share them.
  void showShaded(const GroupPass& pass, int x, int y) {
    if (&pass.samples == &passes_.front().samples)
      observer_.onPixelsDone({x, y, x + 1, y + 1}, pass.samples.means);
  }

  // Each image of samples to the film: shared by all the passes, as the
  // means of as many samples; else each pass's at its offset.
  void addSamplesToFilm() {
    for (GroupPass& pass : passes_) {
      if (!pass.clearsSamples) continue;
      SampleImage& samples = pass.samples;
      if (samples.passes > 1)
        film_.addMeans(std::move(samples.means), samples.passes, workers_);
      else
        film_.addImage(std::move(samples.means), pass.pass.pixelOffset, workers_);
    }
  }

  // A pixel's neighbours, in the order they are tested: left, right, above,
  // below.
  static constexpr std::array<glm::ivec2, 4> kNeighbours{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}};

  bool onImage(glm::ivec2 pixel) const {
    return pixel.x >= 0 && pixel.x < settings_.width && pixel.y >= 0 && pixel.y < settings_.height;
  }

  template <typename Visit>
  void forEachNeighbour(int x, int y, const Visit& visit) const {
    for (const glm::ivec2 step : kNeighbours)
      if (const glm::ivec2 beside{x + step.x, y + step.y}; onImage(beside))
        visit(beside.x, beside.y);
  }

  // The primary ray of the pixel in the pass: through its sample position,
  // from its point of the lens, at its instant. Made again wherever needed,
  // the same to the bit, rather than kept for every pixel of every pass.
  Ray rayAt(const GroupPass& pass, int x, int y) const {
    Ray ray = thinLensRay(
        view_, Vec2(static_cast<float>(x), static_cast<float>(y)) + pass.pass.pixelOffset,
        pass.pass.lens);
    ray.time = pass.pass.time;
    return ray;
  }

  // Pass 1: an item buffer for each pass, its counters into `stats`.
  void fillItemBuffers(std::vector<Stats>& stats, HybridCounters& counters) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < passes_.size(); ++i) {
      GroupPass& pass = passes_[i];
      pass.items = &itemBuffers_.emplace_back(
          context_.scene, tessellated_, projections_.of(pass.recording.index, tessellated_),
          settings_.width, settings_.height, workers_, pass.recording.steps, stats[i]);
    }
    counters.itemBufferSeconds += secondsSince(start);
  }

  const Shape* shapeNumbered(int shape) const {
    return context_.scene.shapes[static_cast<std::size_t>(shape)].get();
  }

  // Intersection tests made for the pixel, into its "cost" where wanted.
  void addCost(GroupPass& pass, int x, int y, std::uint64_t tests) const {
    if (pass.images.cost) pass.images.cost->at(x, y) += Color(static_cast<float>(tests));
  }

  // The nearest hit of the pixel's ray on the item's exact surface alone.
  bool intersect(const Item& item, GroupPass& pass, int x, int y, const Ray& ray, Hit& hit,
                 HybridCounters& counters) {
    const std::uint64_t before = counters.traced.intersections.tests;
    const bool found =
        shapeNumbered(item.shape)
            ->intersectPrimitive(item.primitive, ray, 0.0f, hit, counters.traced.intersections);
    const std::uint64_t tests = counters.traced.intersections.tests - before;
    counters.counts[kItemTests] += tests;
    addCost(pass, x, y, tests);
    return found;
  }

  // The pixel's ray against its own item's exact surface: the hit, or none
  // (its shape none) where the item buffer shows nothing or the ray misses.
  FoundHit ownHit(GroupPass& pass, int x, int y, const Item& own, const Ray& ray,
                  HybridCounters& counters) {
    FoundHit found{ray, own, {}};
    if (own.shape >= 0 && intersect(own, pass, x, y, ray, found.hit, counters))
      found.hit.shape = shapeNumbered(own.shape);
    return found;
  }

  // Marks the pixel as falling back inside an outline, unless it already
  // falls back; whether it did not. Of a pixel being found (FoundHit) or
  // already shaded (Settled, whose verdict is a bit-field: no reference can
  // name it).
  template <typename HasVerdict>
  static bool fallBack(HasVerdict& pixel) {
    if (pixel.verdict != Verdict::FromItemBuffer) return false;
    pixel.verdict = Verdict::Inside;
    return true;
  }

  // Whether `item` meets the pixel's ray before the pixel's own item does,
  // `own` its ray and its hit (at the same distance, the one the structures
  // would pick: the first in the scene's order).
  bool coversNearer(const Item& item, GroupPass& pass, int x, int y, const FoundHit& own,
                    HybridCounters& counters) {
    Hit hit;
    if (!intersect(item, pass, x, y, own.ray, hit, counters)) return false;
    return std::tie(hit.t, item) < std::tie(own.hit.t, own.item);
  }

  // The faces the item buffer shows at the pixel's four neighbours, its own
  // face where a neighbour is off the image. Read without a branch for each,
  // which an edge running through a row would mispredict.
  std::array<int, 4> facesBeside(const ItemBuffer& items, int x, int y, int face) const {
    std::array<int, 4> faces{};
    for (std::size_t i = 0; i < kNeighbours.size(); ++i) {
      const glm::ivec2 beside{x + kNeighbours[i].x, y + kNeighbours[i].y};
      faces[i] = onImage(beside) ? items.faceAt(beside.x, beside.y) : face;
    }
    return faces;
  }

  // Pass 2 begins at each pixel: its ray against its own item's exact
  // surface, then against each other item seen beside it; those that cover
  // it nearer make it fall back, and are the seeds of followOutlines. Inside
  // a polygon, as most pixels are, every neighbour shows the pixel's own
  // face and there is no other item to test.
  FoundHit findHit(GroupPass& pass, int x, int y, const Ray& ray, PassWork& work) {
    const ItemBuffer& items = *pass.items;
    const int face = items.faceAt(x, y);
    const Item own = items.itemOf(face);
    if (pass.clearsSamples) pass.samples.means.at(x, y) = Color(0.0f);
    if (pass.images.cost) pass.images.cost->at(x, y) = Color(0.0f);
    FoundHit found = ownHit(pass, x, y, own, ray, work.counters);
    work.coveredPixels += own.shape >= 0 ? 1 : 0;
    if (pass.images.face) pass.images.face->at(x, y) = Color(static_cast<float>(face));
    if (own.shape >= 0 && !found.hit.shape) found.verdict = Verdict::Outside;
    const std::array<int, 4> beside = facesBeside(items, x, y, face);
    if (std::ranges::count(beside, face) == 4) return found;
    std::array<Item, 4> tested;
    int count = 0;
    for (const int besideFace : beside) {
      if (besideFace == face || besideFace < 0) continue;
      const Item item = items.itemOf(besideFace);
      const auto end = tested.begin() + count;
      if (item == own || std::find(tested.begin(), end, item) != end) continue;
      tested[static_cast<std::size_t>(count++)] = item;
      if (!coversNearer(item, pass, x, y, found, work.counters)) continue;
      fallBack(found);
      work.seeds.push_back({x, y, item});
    }
    return found;
  }

  // From each seed outwards, while the item keeps covering the pixels it
  // reaches: the true outline beyond the polygons. Seldom more than a pixel
  // or two, so done on one thread, once every pixel is shaded: a pixel it
  // reaches that the item buffer answered is shaded again, by a full
  // primary ray. Its first shading's rays stay counted, as the work they
  // were; what it was counted as is taken back.
  void followOutlines(GroupPass& pass, PassWork& work) {
    HybridCounters outlines;
    std::vector<glm::ivec2> shadedAgain;
    std::set<std::tuple<int, int, Item>> tested;
    for (const Seed& seed : work.seeds) tested.insert({seed.x, seed.y, seed.item});
    std::deque<Seed> pending(work.seeds.begin(), work.seeds.end());
    while (!pending.empty()) {
      const Seed seed = pending.front();
      pending.pop_front();
      forEachNeighbour(seed.x, seed.y, [&](int x, int y) {
        if (itemAt(pass, x, y) == seed.item || !tested.insert({x, y, seed.item}).second) return;
        FoundHit found = ownHit(pass, x, y, itemAt(pass, x, y), rayAt(pass, x, y), outlines);
        if (!coversNearer(seed.item, pass, x, y, found, outlines)) return;
        pending.push_back({x, y, seed.item});
        Settled& settled = settledAt(pass, x, y);
        // Already falling back, or the tree pixel, not shaded yet.
        if (!fallBack(settled) || isTreePixel(pass, x, y)) return;
        HybridCounters& counted = work.counters;
        --counted.counts[kFromItemBuffer];
        counted.counts[kSpawning] -= settled.spawnedRays;
        counted.counts[kMirrorOrGlass] -= settled.mirrorOrGlass;
        takeBackSample(pass, x, y, found);
        found.verdict = Verdict::Inside;
        shade(pass, x, y, found, outlines);
        shadedAgain.push_back({x, y});
        showShaded(pass, x, y);
      });
    }
    work.counters += outlines;
    const GroupPass& first = passes_.front();
    if (!shadedAgain.empty() && &pass == &first && first.recording.steps)
      first.recording.steps->record(
          shadedAgainStep(shadedAgain, outlines,
                          [&](int x, int y) { return shownOf(first, x, y); }),
          std::int64_t{2} * settings_.height);
  }

  // Takes the sample that the pixel's shading from the item buffer added
  // out of its pass's image: the same colour, shaded again as it was
  // (first_hit_batch.hpp), its rays not counted twice.
  void takeBackSample(GroupPass& pass, int x, int y, const FoundHit& found) {
    TraceCounters uncounted;
    const Color added = shadeFromItemBuffer(found, uncounted, nullptr).color;
    pass.samples.means.at(x, y) -= added * pass.samples.weight;
  }

  // The pixel whose ray tree is recorded, one for each pass. Its verdict is
  // in memory since it was found, where an outline may have changed it.
  void shadeTreePixels(GroupPass& pass, PassWork& work) {
    for (const auto& [x, y, foundInBand] : work.treePixels) {
      FoundHit found = foundInBand;
      found.verdict = settledAt(pass, x, y).verdict;
      RayTree tree;
      tree.pixel = {x, y};
      tree.sample = pass.recording.index;
      tree.raster = Vec2(x, y) + pass.pass.pixelOffset;
      shade(pass, x, y, found, work.counters, &tree);
      pass.recording.trees->recordTree(std::move(tree));
      showShaded(pass, x, y);
    }
  }

  // What the rows of a band reuse, rather than make again for each.
  struct RowScratch {
    explicit RowScratch(const TracingContext& context) : batch(context) {}

    FirstHitBatch batch;
    struct Batched {
      GroupPass* pass;
      PassWork* work;
      int x;
    };
    std::vector<Batched> batched;  // where each of the batch's hits is from
    std::vector<Ray> rays;         // a run's primary rays, each pixel's passes in turn
  };

  // Pass 2 but the outlines, band by band on the workers, each band's step
  // recorded and its pixels shown as soon as it is done.
  BandWork shadeInBands() {
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

  void shadeBand(const PixelRect& band, BandWork& work) {
    work.passes.resize(passes_.size());
    RowScratch scratch(context_);
    for (int y = band.y0; y < band.y1; ++y) findAndShadeRow(y, band.x0, band.x1, scratch, work);
  }

  // A row's pixels, a run of neighbours at a time: the run's primary rays
  // made first, in a loop of their own, so that the square roots and
  // divisions of one ray's direction do not wait for the last one's shading;
  // then each pixel's first hit found in each pass of the group, and the run
  // shaded. The pixels whose first hits the item buffer gave are shaded as a
  // batch (first_hit_batch.hpp), their shadow rays traced together: each
  // pixel's samples one after another, so that a packet's rays leave from one
  // pixel, or two, towards one light, and meet nearly the same boxes. The
  // others are shaded whole at once; the pixel whose ray tree is recorded,
  // last, its verdict kept till then.
  void findAndShadeRow(int y, int x0, int x1, RowScratch& scratch, BandWork& work) {
    constexpr int kRun = 64;
    FirstHitBatch& batch = scratch.batch;
    SingleRayChoices whitted;
    for (int start = x0; start < x1; start += kRun) {
      batch.clear();
      scratch.batched.clear();
      const int end = std::min(x1, start + kRun);
      scratch.rays.clear();
      for (int x = start; x < end; ++x)
        for (const GroupPass& pass : passes_) scratch.rays.push_back(rayAt(pass, x, y));
      auto ray = scratch.rays.cbegin();
      for (int x = start; x < end; ++x) {
        auto passWork = work.passes.begin();
        for (GroupPass& pass : passes_) {
          PassWork& done = *passWork++;
          const FoundHit found = findHit(pass, x, y, *ray++, done);
          if (isTreePixel(pass, x, y)) {
            settledAt(pass, x, y) = Settled{.verdict = found.verdict};
            done.treePixels.push_back({x, y, found});
            continue;
          }
          if (found.verdict != Verdict::FromItemBuffer || !found.hit.shape) {
            shade(pass, x, y, found, done.counters);
            continue;
          }
          ++done.counters.counts[kFromItemBuffer];
          scratch.batched.push_back({&pass, &done, x});
          batch.add(found.ray, found.hit, whitted, done.counters.traced);
        }
      }
      batch.traceShadowRays();
      for (std::size_t i = 0; i < batch.size(); ++i) {
        const auto& [pass, done, x] = scratch.batched[i];
        HybridCounters& counters = done->counters;
        const IntersectionCounters shadowRayCosts = batch.shadowRayCosts(i);
        counters.traced.intersections += shadowRayCosts;
        addCost(*pass, x, y, shadowRayCosts.tests);
        const RaysSoFar before(counters.traced);
        const SampleResult sample = batch.finish(i, whitted, counters.traced);
        record(*pass, x, y, Verdict::FromItemBuffer, sample, batch.sentShadowRays(i), before,
               counters);
      }
    }
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
  // pixel fell back; its rays recorded in `tree` unless that is null.
  void shade(GroupPass& pass, int x, int y, const FoundHit& found, HybridCounters& counters,
             RayTree* tree = nullptr) {
    const Verdict verdict = found.verdict;
    TraceCounters& traced = counters.traced;
    const RaysSoFar before(traced);
    SampleResult sample;
    if (verdict != Verdict::FromItemBuffer) {
      ++counters.counts[verdict == Verdict::Outside ? kOutside : kInside];
      SingleRayChoices whitted;
      sample = tracePrimary(context_, found.ray, whitted, traced, tree);
    } else {
      ++counters.counts[kFromItemBuffer];
      sample = shadeFromItemBuffer(found, traced, tree);
    }
    record(pass, x, y, verdict, sample, traced.shadowRays > before.shadow, before, counters);
  }

  // Whitted's Shade from the first hit the item buffer gave, the background
  // where it shows nothing.
  SampleResult shadeFromItemBuffer(const FoundHit& found, TraceCounters& traced,
                                   RayTree* tree) const {
    SingleRayChoices whitted;
    const Hit* const seen = found.hit.shape ? &found.hit : nullptr;
    return shadeFirstHit(context_, found.ray, seen, whitted, traced, tree);
  }

  // A pixel's sample, into the pass's images, and how it was shaded and what
  // its shading spawned since `before`, into its record and the counters.
  void record(GroupPass& pass, int x, int y, Verdict verdict, const SampleResult& sample,
              bool spawnedShadowRays, const RaysSoFar& before, HybridCounters& counters) {
    const TraceCounters& traced = counters.traced;
    const bool mirrorOrGlass = traced.reflectionRays + traced.refractionRays > before.mirrorOrGlass;
    const bool spawnedRays = spawnedShadowRays || mirrorOrGlass;
    settledAt(pass, x, y) =
        Settled{.verdict = verdict, .mirrorOrGlass = mirrorOrGlass, .spawnedRays = spawnedRays};
    counters.counts[kSpawning] += spawnedRays;
    counters.counts[kMirrorOrGlass] += mirrorOrGlass;
    addCost(pass, x, y, traced.intersections.tests - before.tests);

    pass.samples.means.at(x, y) += sample.color * pass.samples.weight;
    Images& images = pass.images;
    if (images.depth) images.depth->at(x, y) = Color(sample.depth);
    if (images.normal) images.normal->at(x, y) = sample.normal;
  }

  const TracingContext& context_;
  const TessellatedScene& tessellated_;
  const RenderSettings& settings_;
  PassProjections& projections_;
  Film& film_;
  RenderObserver& observer_;
  const Workers workers_;
  const ViewFrame view_;
  std::deque<SampleImage> sampleImages_;  // a deque: the passes point to theirs
  std::deque<GroupPass> passes_;          // a deque: a pass's images point into the pass
  std::deque<ItemBuffer> itemBuffers_;    // a pass's, which it points to
};

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
                                   (sizeof(Settled) + images * sizeof(Color)));
  return static_cast<int>(std::clamp<std::size_t>(kGroupBytes / passBytes, 1, kPasses));
}

}  // namespace

RenderResult HybridRenderer::render(const Scene& scene, const RenderSettings& settings,
                                    RenderObserver& observer) const {
  const SceneIntersector intersector(scene, settings.accel, settings.threads);
  const TracingContext context{scene, intersector, settings.maxDepth};
  HybridCounters counters;
  std::vector<SettledPixels> settled;
  RenderResult result = renderInPassGroups(
      scene, settings, observer, largestGroup(settings),
      [&](const TessellatedScene& tessellated, std::span<const AccumulationPass> passes,
          int firstPass, PassProjections& projections, Film& film, RenderObserver& groupObserver) {
        return HybridGroup(context, tessellated, settings, passes, firstPass, projections, film,
                           groupObserver, observer.stepRecorder(), settled)
            .run(counters);
      });
  addHybridStats(result.stats, counters);
  intersector.addBuildStats(result.stats);
  return result;
}

}  // namespace rise
