// The hybrid algorithm's pass 2 along a row (hybrid.cpp): each pixel's first
// hit found from the item buffer (hybrid_silhouettes.cpp), then Whitted's
// Shade from it. The first hits of a run of neighbours being known before
// any is shaded, the run is shaded as a batch whose shadow rays go through
// the structure together, a packet towards each light (first_hit_batch.hpp):
// the same rays and colours as one pixel at a time, at less cost. A pixel
// that falls back is traced whole, Whitted's primary ray and all.
#include <algorithm>

#include "hybrid/hybrid_group.hpp"

namespace rise::hybrid {

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
void HybridGroup::findAndShadeRow(int y, int x0, int x1, RowScratch& scratch, BandWork& work) {
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

// Whitted's Shade from the item's hit, or his whole primary ray where the
// pixel fell back; its rays recorded in `tree` unless that is null.
void HybridGroup::shade(GroupPass& pass, int x, int y, const FoundHit& found,
                        HybridCounters& counters, RayTree* tree) {
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
SampleResult HybridGroup::shadeFromItemBuffer(const FoundHit& found, TraceCounters& traced,
                                              RayTree* tree) const {
  SingleRayChoices whitted;
  const Hit* const seen = found.hit.shape ? &found.hit : nullptr;
  return shadeFirstHit(context_, found.ray, seen, whitted, traced, tree);
}

// A pixel's sample, into the pass's images, and how it was shaded and what
// its shading spawned since `before`, into its record and the counters.
void HybridGroup::record(GroupPass& pass, int x, int y, Verdict verdict, const SampleResult& sample,
                         bool spawnedShadowRays, const RaysSoFar& before,
                         HybridCounters& counters) {
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

// The pixel whose ray tree is recorded, one for each pass. Its verdict is
// in memory since it was found, where an outline may have changed it.
void HybridGroup::shadeTreePixels(GroupPass& pass, PassWork& work) {
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

}  // namespace rise::hybrid
