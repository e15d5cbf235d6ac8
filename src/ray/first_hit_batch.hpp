// First hits shaded together, so that their shadow rays are traced together.
// Each hit is shaded up to its shadow rays as it is added (FirstHitShading,
// ray_tracing.hpp); then all the batch's shadow rays go through the
// acceleration structure eight at a time towards one light, as packets:
// rays from neighbouring points towards one light meet the same boxes, and a
// packet loads each box once for all of them. Then each hit's shading is
// finished. Colours and rays are those of shadeFirstHit, hit by hit. Whitted's
// recursion, one ray after another, cannot gather rays so; a caller that
// knows many first hits before it shades any (the hybrid algorithm, a run of
// a row's pixels) can.
#pragma once

#include <cstddef>
#include <vector>

#include "ray/ray_tracing.hpp"

namespace rise {

class FirstHitBatch {
 public:
  explicit FirstHitBatch(const TracingContext& context) : context_(context) {}

  // Empties the batch, keeping its memory for the next.
  void clear();

  // Shades the primary ray's hit up to its shadow rays, as the batch's next
  // hit (numbered from 0 in the order added).
  void add(const Ray& ray, const Hit& hit, PathChoices& choices, TraceCounters& counters);

  std::size_t size() const { return hits_.size(); }

  // Traces every hit's shadow rays, a packet towards one light at a time,
  // the hits' rays in the order the hits were added.
  void traceShadowRays();

  // Of hit i, once the shadow rays are traced: whether it sent any, and what
  // they cost, for the caller to count where the hit belongs.
  bool sentShadowRays(std::size_t i) const;
  IntersectionCounters shadowRayCosts(std::size_t i) const;

  // Hit i's shading finished: the lights' terms, then its reflected and
  // refracted rays.
  SampleResult finish(std::size_t i, PathChoices& choices, TraceCounters& counters) const;

 private:
  const TracingContext& context_;
  std::vector<FirstHitShading> hits_;
  std::vector<LitShadowRay> shadowRays_;
  std::vector<Color> visible_;                     // what each shadow ray let through
  std::vector<IntersectionCounters> shadowCosts_;  // and what it cost
};

}  // namespace rise
