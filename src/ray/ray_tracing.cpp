#include "ray/ray_tracing.hpp"

#include "ray/image_sampler.hpp"
#include "ray/recursive_tracer.hpp"

namespace rise {
namespace {

class PinholeTracer final : public SampleTracer {
 public:
  PinholeTracer(const Scene& scene, const SceneIntersector& intersector,
                const RenderSettings& settings)
      : view_(scene.camera, settings.width, settings.height),
        tracer_(scene, intersector, settings.maxDepth) {}

  SampleResult trace(const CameraSample& sample, Rng&, TraceCounters& counters) const override {
    CentredPathSampler centred;
    return tracer_.tracePrimary(view_.primaryRay(sample.raster.x, sample.raster.y), centred,
                                counters);
  }
  bool usesEffectSamples() const override { return false; }

 private:
  ViewFrame view_;
  RecursiveTracer tracer_;
};

}  // namespace

RenderResult WhittedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                      RenderObserver& observer) const {
  return renderByTracing<PinholeTracer>(scene, settings, observer);
}

}  // namespace rise
