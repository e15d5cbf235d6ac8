// Eye-light shading: each surface lit by a light at the eye, its colour times
// the cosine between the surface and the ray that sees it, and nothing else.
#include "eye_light.hpp"

#include <glm/geometric.hpp>

#include "ray/shading_frame.hpp"

namespace rise {

const AlgorithmDescription& EyeLight::description() const {
  static const AlgorithmDescription description =
      rayTracingAlgorithm("eye-light", "Each surface lit from the eye", "none", {});
  return description;
}

RenderResult EyeLight::render(const Scene& scene, const RenderSettings& settings,
                              RenderObserver& observer) const {
  return traceTiles(scene, settings, observer, [&](const TracingContext& context, TileTrace& tile) {
    traceEachSample(
        tile, settings, {.squares = 1},
        [&](const Vec2& raster, SampleValues& values, TraceCounters& counters, RayTree*) {
          const Ray ray = thinLensRay(context.view, raster, values.next2D());
          ++counters.primaryRays;
          Hit hit;
          if (!context.intersector.nearest(ray, 0.0f, hit, counters.intersections))
            return SampleResult{scene.image.background};
          const Material& material = scene.materialOf(*hit.shape);
          const ShadingFrame frame = shadingFrame(ray, hit, material);
          const float cosine = glm::dot(frame.shadingNormal, frame.toViewer);
          return SampleResult{cosine * material.color, hit.t, frame.surface.normal};
        });
  });
}

}  // namespace rise
