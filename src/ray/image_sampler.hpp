// How a ray tracer turns samples into an image: for each pixel, a set of
// camera samples placed by the render's pattern, each traced and added to the
// film under the reconstruction filter; or, for the adaptive pattern,
// Whitted's (1980) refinement of the pixel's square wherever its corners
// disagree.
//
// A camera sample has five dimensions, each in [0, 1): where in the pixel,
// where on the lens, when in the shutter interval, where on an area light,
// where in a gloss lobe. Following Cook (1986, "Stochastic sampling in
// computer graphics"), each dimension's n values are stratified (jittered)
// on their own and then shuffled, so that every dimension is well spread and
// no two are correlated: the sample in the pixel's top-left cell does not
// always take the lens's top-left too.
#pragma once

#include "core/random.hpp"
#include "ray/scene_intersector.hpp"
#include "ray/trace_counters.hpp"
#include "render/renderer.hpp"

namespace rise {

struct CameraSample {
  Vec2 raster;  // the continuous raster position: pixel (i, j) covers [i, i+1) x [j, j+1)
  Vec2 lens;
  float time;
  Vec2 light;
  Vec2 gloss;
};

// What tracing one camera sample found: its colour, and for the auxiliary
// buffers what the primary ray hit.
struct SampleResult {
  Color color;
  float depth = kInfinity;
  Vec3 normal{0.0f};
};

// A ray tracer, as the image sampler sees it.
class SampleTracer {
 public:
  virtual ~SampleTracer() = default;
  virtual SampleResult trace(const CameraSample& sample, Rng& rng,
                             TraceCounters& counters) const = 0;
  // Whether it reads the dimensions beyond the pixel (lens, time, light,
  // gloss). A tracer that does not is given their centres, and the sampler
  // spares itself stratifying and shuffling them for every pixel.
  virtual bool usesEffectSamples() const = 0;
};

// Renders the image by sampling every pixel with `tracer`, in parallel tiles,
// and returns it with the auxiliary buffers (taken from each pixel's first
// sample; with the adaptive pattern, its top-left corner) and the counters.
RenderResult renderBySampling(const RenderSettings& settings, RenderObserver& observer,
                              const SampleTracer& tracer);

// The same with a `Tracer(scene, intersector, settings)` over the scene's
// acceleration structure, built first, whose build statistics are added.
template <typename Tracer>
RenderResult renderByTracing(const Scene& scene, const RenderSettings& settings,
                             RenderObserver& observer) {
  const SceneIntersector intersector(scene, settings.accel, settings.threads);
  RenderResult result = renderBySampling(settings, observer, Tracer(scene, intersector, settings));
  intersector.addBuildStats(result.stats);
  return result;
}

}  // namespace rise
