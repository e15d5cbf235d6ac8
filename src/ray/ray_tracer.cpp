#include "ray/ray_tracer.hpp"

#include <utility>

#include "ray/adaptive_supersampling.hpp"
#include "render/render_limits.hpp"

namespace rise {
namespace {

// The film (a weighted sum and a weight), the image, the auxiliary buffers
// and the images written from them.
constexpr std::uint64_t kRayTracingBytesPerPixel = 112;

}  // namespace

AlgorithmDescription rayTracingAlgorithm(std::string_view name, std::string_view summary,
                                         std::string_view citation, std::vector<Effect> effects) {
  return {.name = name,
          .summary = summary,
          .citation = citation,
          .family = Family::RayTracing,
          .buffers = {"depth", "normal", "cost"},
          .options = {Option::Accel, Option::MaxDepth},
          .effects = std::move(effects),
          .looks = {Look::Steps, Look::RayTrees},
          .tileStatistics = TileStatistics::Summed};
}

RenderNeeds RayTracer::needs(const Scene& scene, const RenderSettings& settings) const {
  RenderNeeds needs = memoryNeeds(scene, settings, kRayTracingBytesPerPixel);
  needs.rays = recursionRays(scene, settings);
  return needs;
}

RenderResult renderWithRays(const Scene& scene, const RenderSettings& settings,
                            const std::function<RenderResult(const TracingContext&)>& render) {
  const SceneIntersector intersector(scene, settings.accel, settings.threads);
  const TracingContext context{scene, intersector, settings.maxDepth,
                               ViewFrame(scene.camera, settings.width, settings.height)};
  RenderResult result = render(context);
  intersector.addBuildStats(result.stats);
  return result;
}

RenderResult traceTiles(const Scene& scene, const RenderSettings& settings,
                        RenderObserver& observer, const TileTracer& traceTile) {
  return renderWithRays(scene, settings, [&](const TracingContext& context) {
    return traceImage(settings, observer, [&](TileTrace& tile) { traceTile(context, tile); });
  });
}

void traceEachSample(TileTrace& tile, const RenderSettings& settings, SampleLayout layout,
                     const TraceSample& trace) {
  if (settings.sampling.pattern == SamplePattern::Adaptive)
    return sampleAdaptively(tile, settings, trace);
  Sampler sampler(layout);
  const std::vector<Vec2>* offsets = nullptr;
  tracePixels(
      tile, settings.seed,
      [&](const glm::ivec2&, Rng& rng) -> const std::vector<Vec2>& {
        offsets = &sampler.startPixel(settings.sampling, rng);
        return *offsets;
      },
      [&](const glm::ivec2& pixel, int i, Rng& rng, TraceCounters& counters, RayTree* tree) {
        SampleValues values = sampler.valuesOf(i, rng);
        return trace(Vec2(pixel) + (*offsets)[static_cast<std::size_t>(i)], values, counters, tree);
      });
}

}  // namespace rise
