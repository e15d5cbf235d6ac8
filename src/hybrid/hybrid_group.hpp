// The hybrid algorithm's group of accumulation passes (hybrid.cpp), whose
// work is told in four files, an idea each: the two passes (hybrid.cpp), the
// silhouette rule (hybrid_silhouettes.cpp), shading along rows
// (hybrid_row_shading.cpp) and the bookkeeping of a pass (hybrid_pass.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "hybrid/hybrid_pass.hpp"
#include "ray/first_hit_batch.hpp"
#include "ray/ray_tracing.hpp"

namespace rise::hybrid {

// Both passes of a group of accumulation passes: pass 1 for each, then pass
// 2 for them all, a pixel's samples one after another.
class HybridGroup {
 public:
  HybridGroup(const TracingContext& context, const TessellatedScene& tessellated,
              const RenderSettings& settings, std::span<const AccumulationPass> passes,
              int firstPass, PassProjections& projections, Film& film, RenderObserver& observer,
              StepRecorder* trees, std::vector<SettledPixels>& settled);

  std::vector<RenderResult> run(HybridCounters& counters);

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
  // The counts of the rays traced so far, to tell what a pixel's shading
  // spawned.
  struct RaysSoFar {
    explicit RaysSoFar(const TraceCounters& traced)
        : shadow(traced.shadowRays),
          mirrorOrGlass(traced.reflectionRays + traced.refractionRays),
          tests(traced.intersections.tests) {}

    std::uint64_t shadow, mirrorOrGlass, tests;
  };

  // The bookkeeping of a pass (hybrid_pass.cpp).
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
  void showShaded(const GroupPass& pass, int x, int y);
  void addSamplesToFilm();
  // The primary ray of the pixel in the pass: through its sample position,
  // from its point of the lens, at its instant. Made again wherever needed,
  // the same to the bit, rather than kept for every pixel of every pass.
  Ray rayAt(const GroupPass& pass, int x, int y) const {
    Ray ray = thinLensRay(
        context_.view, Vec2(static_cast<float>(x), static_cast<float>(y)) + pass.pass.pixelOffset,
        pass.pass.lens);
    ray.time = pass.pass.time;
    return ray;
  }
  // Intersection tests made for the pixel, into its "cost" where wanted.
  void addCost(GroupPass& pass, int x, int y, std::uint64_t tests) const {
    if (pass.images.cost) pass.images.cost->at(x, y) += Color(static_cast<float>(tests));
  }
  const Shape* shapeNumbered(int shape) const {
    return context_.scene.shapes[static_cast<std::size_t>(shape)].get();
  }

  // Pass 1, and pass 2 band by band (hybrid.cpp).
  void fillItemBuffers(std::vector<Stats>& stats, HybridCounters& counters);
  BandWork shadeInBands();
  void shadeBand(const PixelRect& band, BandWork& work);

  // The silhouette rule (hybrid_silhouettes.cpp).
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
  bool intersect(const Item& item, GroupPass& pass, int x, int y, const Ray& ray, Hit& hit,
                 HybridCounters& counters);
  FoundHit ownHit(GroupPass& pass, int x, int y, const Item& own, const Ray& ray,
                  HybridCounters& counters);
  bool coversNearer(const Item& item, GroupPass& pass, int x, int y, const FoundHit& own,
                    HybridCounters& counters);
  std::array<int, 4> facesBeside(const ItemBuffer& items, int x, int y, int face) const;
  FoundHit findHit(GroupPass& pass, int x, int y, const Ray& ray, PassWork& work);
  void followOutlines(GroupPass& pass, PassWork& work);
  void takeBackSample(GroupPass& pass, int x, int y, const FoundHit& found);

  // Shading along rows (hybrid_row_shading.cpp).
  void findAndShadeRow(int y, int x0, int x1, RowScratch& scratch, BandWork& work);
  void shade(GroupPass& pass, int x, int y, const FoundHit& found, HybridCounters& counters,
             RayTree* tree = nullptr);
  SampleResult shadeFromItemBuffer(const FoundHit& found, TraceCounters& traced,
                                   RayTree* tree) const;
  void record(GroupPass& pass, int x, int y, Verdict verdict, const SampleResult& sample,
              bool spawnedShadowRays, const RaysSoFar& before, HybridCounters& counters);
  void shadeTreePixels(GroupPass& pass, PassWork& work);

  const TracingContext& context_;
  const TessellatedScene& tessellated_;
  const RenderSettings& settings_;
  PassProjections& projections_;
  Film& film_;
  RenderObserver& observer_;
  const Workers workers_;
  std::deque<SampleImage> sampleImages_;  // a deque: the passes point to theirs
  std::deque<GroupPass> passes_;          // a deque: a pass's images point into the pass
  std::deque<ItemBuffer> itemBuffers_;    // a pass's, which it points to
};

}  // namespace rise::hybrid
