#include "raster/visible_surface_renderer.hpp"

#include "core/random.hpp"
#include "core/sampling.hpp"
#include "render/film.hpp"
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
  tessellation.time = 0.0f;  // the shutter's opening, as Whitted's ray tracer sees it
  return tessellateScene(scene, tessellation);
}

namespace {

// The sub-pixel offsets of the accumulation buffer's passes: the render's
// sample pattern, the same in every pixel. Adaptive refinement needs a pixel
// of its own to refine, which a whole-frame pass is not, so it takes
// jittered offsets.
std::vector<Vec2> passOffsets(const RenderSettings& settings) {
  const PixelSampling& sampling = settings.sampling;
  const SamplePattern pattern =
      sampling.pattern == SamplePattern::Adaptive ? SamplePattern::Jittered : sampling.pattern;
  Rng rng(settings.seed);
  std::vector<Vec2> offsets;
  samplePositions(pattern, sampling.samples, rng, offsets);
  return offsets;
}

// Reports the progress of one pass as its share of all of them.
class PassObserver final : public RenderObserver {
 public:
  PassObserver(RenderObserver& whole, int pass, int passes)
      : whole_(whole), pass_(pass), passes_(passes) {}
  void onProgress(double fractionDone) override {
    whole_.onProgress((pass_ + fractionDone) / passes_);
  }
  bool cancelled() const override { return whole_.cancelled(); }

 private:
  RenderObserver& whole_;
  int pass_;
  int passes_;
};

}  // namespace

// Anti-aliasing by accumulation (Haeberli & Akeley 1990): one whole image a
// sample offset, each image's pixels added to the film as samples at that
// offset, so that the reconstruction filter weighs them as it weighs the ray
// tracers' samples. The auxiliary buffers are the first pass's, but "cost",
// which adds up over the passes, as do the counters.
RenderResult VisibleSurfaceRenderer::render(const Scene& scene, const RenderSettings& settings,
                                            RenderObserver& observer) const {
  const TessellatedScene tessellated = tessellateForRaster(scene, settings);
  const std::vector<Vec2> offsets = passOffsets(settings);
  const int passes = static_cast<int>(offsets.size());
  Film film(settings.width, settings.height, settings.sampling.filter);
  FilmTile filmTile = film.tileFor(Tile{0, 0, 0, settings.width, settings.height});

  RenderResult accumulated;
  for (int pass = 0; pass < passes && !observer.cancelled(); ++pass) {
    PassObserver passObserver(observer, pass, passes);
    RenderResult result = renderSample(scene, tessellated, settings, offsets[pass], passObserver);
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x)
        filmTile.addSample({x, y}, offsets[pass], result.image.at(x, y));
    if (pass == 0) {
      accumulated = std::move(result);
      continue;
    }
    accumulated.stats.accumulate(result.stats);
    Image& cost = accumulated.buffers.at("cost");
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x) cost.at(x, y) += result.buffers.at("cost").at(x, y);
  }
  film.merge(filmTile);
  accumulated.image = film.resolve();
  const double covered = accumulated.stats.value("covered_pixels");
  accumulated.stats.add("overdraw",
                        covered > 0.0 ? accumulated.stats.value("pixels_written") / covered : 0.0);
  accumulated.stats.add("samples_per_pixel", passes);
  return accumulated;
}

RenderResult VisibleSurfaceRenderer::renderSample(const Scene& scene,
                                                  const TessellatedScene& tessellated,
                                                  const RenderSettings& settings, Vec2 sampleOffset,
                                                  RenderObserver& observer) const {
  const int threads = resolveThreadCount(settings.threads);
  const ViewProjection view(ViewFrame(scene.camera, settings.width, settings.height), sampleOffset);
  const ScreenGeometry screen = projectScene(tessellated, view, settings.backfaceCulling, threads);
  const SurfaceShader shader(scene, tessellated, screen, view, settings.shading, threads);
  RasterFrame frame(settings.width, settings.height, scene.image.background, screen, shader,
                    threads);

  Stats stats;
  addProjectionStats(stats, screen);
  resolveVisibility(screen, settings, observer, frame, stats);
  stats.add("covered_pixels", static_cast<double>(frame.coveredPixels()));

  RenderResult result = frame.takeResult();
  result.stats = std::move(stats);
  return result;
}

}  // namespace rise
