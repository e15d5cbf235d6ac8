#include "ray/distributed_ray_tracing.hpp"

#include "ray/image_sampler.hpp"
#include "ray/recursive_tracer.hpp"

namespace rise {
namespace {

// The path's choices: at the surface seen from the eye, the camera sample's
// own stratified light and gloss values; deeper, fresh random ones.
class StratifiedPathSampler final : public PathSampler {
 public:
  StratifiedPathSampler(const CameraSample& sample, Rng& rng) : sample_(sample), rng_(rng) {}

  Vec2 lightSample(int depth) override { return depth == 1 ? sample_.light : random(); }
  Vec2 glossSample(int depth) override { return depth == 1 ? sample_.gloss : random(); }

 private:
  Vec2 random() { return {rng_.uniform(), rng_.uniform()}; }

  const CameraSample& sample_;
  Rng& rng_;
};

class ThinLensTracer final : public SampleTracer {
 public:
  ThinLensTracer(const Scene& scene, const SceneIntersector& intersector,
                 const RenderSettings& settings)
      : view_(scene.camera, settings.width, settings.height),
        tracer_(scene, intersector, settings.maxDepth),
        motionBlur_(scene.camera.hasMotionBlur()) {}

  SampleResult trace(const CameraSample& sample, Rng& rng, TraceCounters& counters) const override {
    Ray ray = view_.thinLensRay(sample.raster, sample.lens);
    // Rays carry the time as a fraction of the shutter interval: moving
    // shapes are where that fraction of their motion has taken them.
    ray.time = motionBlur_ ? sample.time : 0.0f;
    StratifiedPathSampler paths(sample, rng);
    return tracer_.tracePrimary(ray, paths, counters);
  }
  bool usesEffectSamples() const override { return true; }

 private:
  ViewFrame view_;
  RecursiveTracer tracer_;
  bool motionBlur_;
};

}  // namespace

RenderResult DistributedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                          RenderObserver& observer) const {
  return renderByTracing<ThinLensTracer>(scene, settings, observer);
}

}  // namespace rise
