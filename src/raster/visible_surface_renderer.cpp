#include "raster/visible_surface_renderer.hpp"

#include "render/tiles.hpp"

namespace rise {
namespace {

void addProjectionStats(Stats& stats, const ScreenGeometry& screen) {
  const ProjectionCounters& counters = screen.counters;
  stats.add("polygons_in", static_cast<double>(counters.polygonsIn));
  stats.add("polygons_culled", static_cast<double>(counters.culled));
  stats.add("polygons_outside_view", static_cast<double>(counters.outside));
  stats.add("polygons_clipped", static_cast<double>(counters.clipped));
  stats.add("polygons_drawn", static_cast<double>(screen.polygons.size()));
}

}  // namespace

TessellatedScene tessellateForRaster(const Scene& scene, const RenderSettings& settings) {
  TessellationSettings tessellation;
  tessellation.level = settings.tessellation;
  tessellation.planeSize = settings.planeSize;
  tessellation.viewpoint = scene.camera.position;
  tessellation.time = scene.camera.shutterOpen;
  return tessellateScene(scene, tessellation);
}

RenderResult VisibleSurfaceRenderer::render(const Scene& scene, const RenderSettings& settings,
                                            RenderObserver& observer) const {
  return renderSample(scene, tessellateForRaster(scene, settings), settings, Vec2(0.5f), observer);
}

RenderResult VisibleSurfaceRenderer::renderSample(const Scene& scene,
                                                  const TessellatedScene& tessellated,
                                                  const RenderSettings& settings,
                                                  Vec2 sampleOffset,
                                                  RenderObserver& observer) const {
  const int threads = resolveThreadCount(settings.threads);
  const ViewProjection view(ViewFrame(scene.camera, settings.width, settings.height),
                            sampleOffset);
  const ScreenGeometry screen = projectScene(tessellated, view, settings.backfaceCulling, threads);
  const SurfaceShader shader(scene, tessellated, screen, view, settings.shading, threads);
  RasterFrame frame(settings.width, settings.height, scene.image.background, screen, shader);

  Stats stats;
  addProjectionStats(stats, screen);
  resolveVisibility(screen, settings, observer, frame, stats);
  const std::uint64_t covered = frame.coveredPixels();
  stats.add("overdraw", covered > 0 ? stats.value("pixels_written") / static_cast<double>(covered)
                                    : 0.0);

  RenderResult result = frame.takeResult();
  result.stats = std::move(stats);
  return result;
}

}  // namespace rise
