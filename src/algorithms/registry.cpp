#include "algorithms/registry.hpp"

#include <tuple>

#include "core/elapsed.hpp"
#include "hybrid/hybrid.hpp"
#include "radiosity/radiosity.hpp"
#include "raster/area_subdivision.hpp"
#include "raster/depth_sort.hpp"
#include "raster/scanline.hpp"
#include "raster/z_buffer.hpp"
#include "ray/distributed_ray_tracing.hpp"
#include "ray/path_tracing.hpp"
#include "ray/ray_tracing.hpp"

namespace rise {

namespace {

// One instance of each algorithm, made once, in the order given.
template <typename... Algorithm>
std::span<const Renderer* const> tableOf() {
  static const std::tuple<Algorithm...> algorithms;
  static const Renderer* const table[] = {&std::get<Algorithm>(algorithms)...};
  return table;
}

}  // namespace

std::span<const Renderer* const> allRenderers() {
  // One line an algorithm.
  // clang-format off
  return tableOf<
      DepthSortRenderer,
      AreaSubdivisionRenderer,
      ZBufferRenderer,
      ScanlineRenderer,
      WhittedRayTracer,
      DistributedRayTracer,
      HybridRenderer,
      PathTracer,
      RadiosityRenderer>();
  // clang-format on
}

const Renderer* findRenderer(std::string_view name) {
  for (const Renderer* renderer : allRenderers())
    if (renderer->name() == name) return renderer;
  return nullptr;
}

const Renderer& defaultRenderer(Use use) {
  // Whitted's ray tracer draws the most of a scene at once: shadows, mirrors
  // and glass; the scanline algorithm's steps, a scanline each, are the
  // easiest to follow.
  switch (use) {
    case Use::Explain:
      return *findRenderer("scanline");
    case Use::Render:
    case Use::Inspect:
      break;
  }
  return *findRenderer("ray-tracing");
}

std::vector<const Renderer*> defaultComparison() {
  // Whitted's shadows, mirror and glass beside Catmull's depth buffer: the
  // two families' best-known algorithms.
  return {findRenderer("ray-tracing"), findRenderer("z-buffer")};
}

std::vector<const Renderer*> renderersOffering(Look look) {
  std::vector<const Renderer*> offering;
  for (const Renderer* renderer : allRenderers())
    if (renderer->description().offers(look)) offering.push_back(renderer);
  return offering;
}

RenderResult renderTimed(const Renderer& renderer, const Scene& scene,
                         const RenderSettings& settings, RenderObserver& observer) {
  RenderResult result;
  const double seconds = secondsOf([&] { result = renderer.render(scene, settings, observer); });
  result.stats.add("render_seconds", seconds);
  if (const double rays = result.stats.value("rays"); rays > 0.0)
    result.stats.add("rays_per_second", rays / seconds);
  return result;
}

}  // namespace rise
