// Whitted ray tracing (ray_tracing.cpp tells it), and what Cook's distributed
// ray tracing (distributed_ray_tracing.cpp) and the hybrid take from it: the
// recursion, with the choices a path makes left open (path_choices.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "ray/path_choices.hpp"
#include "ray/ray_tracer.hpp"
#include "ray/shading_frame.hpp"

namespace rise {

class WhittedRayTracer final : public RayTracer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

// Whitted's recursive Intersect and Shade, from a ray that leaves the eye:
// the colour seen along it, and what it hit; every ray recorded in `tree`
// when there is one.
SampleResult tracePrimary(const TracingContext& context, const Ray& ray, PathChoices& choices,
                          TraceCounters& counters, RayTree* tree = nullptr);

// The same once the primary ray's nearest hit is known (nullptr: it hits
// nothing), found by other means than the ray's search (the hybrid
// algorithm's item buffer): Shade, and the rays it spawns. The primary ray is
// not counted.
SampleResult shadeFirstHit(const TracingContext& context, const Ray& ray, const Hit* hit,
                           PathChoices& choices, TraceCounters& counters, RayTree* tree = nullptr);

// The same for a primary ray whose search of the scene, already counted,
// found `hit` (nullptr: nothing), as a packet of rays finds it: the ray
// counted, then shaded.
SampleResult shadeSearchedPrimary(const TracingContext& context, const Ray& ray, const Hit* hit,
                                  PathChoices& choices, TraceCounters& counters, RayTree* tree);

// A shadow ray that Shade sends towards a light, and what the light's Phong
// terms add to the point where the light arrives unfiltered.
struct LitShadowRay {
  Ray ray;
  float distance = 0.0f;  // to the light, along the ray
  Color lit{0.0f};
  int light = 0;  // the light's place among the scene's
};

// Shade at a primary ray's first hit, cut in two where its shadow rays are
// traced: shading many first hits, a caller may trace all their shadow rays
// between the two halves, together (first_hit_batch.hpp). The two halves
// give shadeFirstHit's colour, to the bit, and count the same rays.
class FirstHitShading {
 public:
  // The first half: the point, its ambient term, and the shadow rays it
  // needs, added to `shadowRays` (the primary ray is not counted).
  FirstHitShading(const TracingContext& context, const Ray& ray, const Hit& hit,
                  PathChoices& choices, TraceCounters& counters,
                  std::vector<LitShadowRay>& shadowRays);

  // The second half, given what each shadow ray let through (`visible`, in
  // the order of `shadowRays`): the lights' terms, then the reflected and
  // refracted rays.
  SampleResult finish(const TracingContext& context, PathChoices& choices, TraceCounters& counters,
                      const std::vector<LitShadowRay>& shadowRays,
                      const std::vector<Color>& visible) const;

  // Its own shadow rays' places in the list the first half added them to:
  // [firstShadowRay(), endOfShadowRays()).
  std::size_t firstShadowRay() const { return firstShadowRay_; }
  std::size_t endOfShadowRays() const { return endOfShadowRays_; }

 private:
  ShadingFrame frame_;
  const Material* material_;
  Color ambient_;
  SampleResult seen_;
  std::size_t firstShadowRay_, endOfShadowRays_;
};

}  // namespace rise
