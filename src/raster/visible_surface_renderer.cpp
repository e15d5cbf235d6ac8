#include "raster/visible_surface_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <ctime>
#include <optional>
#include <string>
#include <utility>

#include "core/elapsed.hpp"
#include "core/random.hpp"
#include "core/sampler.hpp"
#include "core/text.hpp"
#include "raster/shadow_map.hpp"
#include "render/film.hpp"
#include "render/render_limits.hpp"

namespace rise {

ShadowMapSettings shadowMapSettings(const RenderSettings& settings) {
  return {settings.shadowMapSize, settings.shadowBias, settings.shadowFilter};
}

void addProjectionStats(Stats& stats, const ScreenGeometry& screen) {
  const ProjectionCounters& counters = screen.counters;
  stats.add("polygons_in", static_cast<double>(counters.polygonsIn));
  stats.add("polygons_culled", static_cast<double>(counters.culled));
  stats.add("polygons_outside_view", static_cast<double>(counters.outside));
  stats.add("polygons_clipped", static_cast<double>(counters.clipped));
  stats.add("polygons_drawn", static_cast<double>(screen.polygons.size()));
}

namespace {

// The film (a weighted sum and a weight), the image, the auxiliary buffers
// and the images written from them, each pass's own image and buffers and
// their frame's per-pixel arrays.
constexpr std::uint64_t kVisibleSurfaceBytesPerPixel = 200;
// A triangle of the tessellation, its face and its polygon on the screen,
// with the lists the algorithms keep of them (area subdivision's, the
// largest, measured at some 190 bytes).
constexpr std::uint64_t kBytesPerTessellatedTriangle = 200;

std::uint64_t tessellatedTriangles(const Scene& scene, int level) {
  std::uint64_t triangles = 0;
  for (const auto& shape : scene.shapes) triangles += shape->tessellatedTriangles(level);
  return triangles;
}

}  // namespace

AlgorithmDescription visibleSurfaceAlgorithm(std::string_view name, std::string_view summary,
                                             std::string_view citation,
                                             std::vector<Effect> ownEffects,
                                             std::vector<Option> ownOptions,
                                             std::vector<ShadowMethod> ownShadowMethods) {
  std::vector<Effect> effects = {Effect::Shadows, Effect::DepthOfField, Effect::MotionBlur};
  effects.insert(effects.end(), ownEffects.begin(), ownEffects.end());
  std::vector<Option> options = {Option::Shading, Option::Culling, Option::Tessellation,
                                 Option::PlaneSize, Option::Shadows};
  options.insert(options.end(), ownOptions.begin(), ownOptions.end());
  std::vector<ShadowMethod> shadowMethods = {ShadowMethod::Map};
  shadowMethods.insert(shadowMethods.end(), ownShadowMethods.begin(), ownShadowMethods.end());
  return {name,
          summary,
          citation,
          Family::VisibleSurface,
          {"depth", "normal", "cost", "face", "shadow-map"},
          std::move(options),
          std::move(effects),
          {},
          std::move(shadowMethods),
          {Look::Steps},
          TileStatistics::WholeImage};
}

RenderNeeds visibleSurfaceNeeds(const Scene& scene, const RenderSettings& settings) {
  RenderNeeds needs = memoryNeeds(scene, settings, kVisibleSurfaceBytesPerPixel);
  std::uint64_t largest = needs.bytes;
  const auto add = [&](std::uint64_t bytes, std::string what, std::string toTakeLess) {
    needs.bytes += bytes;
    if (bytes <= largest) return;
    largest = bytes;
    needs.mostOfTheMemory = std::move(what);
    needs.toTakeLess = std::move(toTakeLess);
  };
  const std::uint64_t triangles = tessellatedTriangles(scene, settings.tessellation);
  add(triangles * kBytesPerTessellatedTriangle,
      "the " + grouped(triangles) + " triangles of --tessellation " +
          std::to_string(settings.tessellation),
      "a lower --tessellation");
  if (settings.shadows == ShadowMethod::Map) {
    const std::string side = std::to_string(settings.shadowMapSize);
    add(shadowMapBytes(scene, shadowMapSettings(settings)),
        "the shadow maps of " + counted(scene.lights.size(), "light") + ", " + side + " x " + side +
            " texels each",
        "smaller shadow maps (--shadow-map-size)");
  }
  return needs;
}

RenderNeeds VisibleSurfaceRenderer::needs(const Scene& scene,
                                          const RenderSettings& settings) const {
  return visibleSurfaceNeeds(scene, settings);
}

TessellatedScene tessellateForRaster(const Scene& scene, const RenderSettings& settings,
                                     float time) {
  TessellationSettings tessellation;
  tessellation.level = settings.tessellation;
  tessellation.planeSize = settings.planeSize;
  tessellation.viewpoint = scene.camera.position;
  tessellation.time = time;
  return tessellateScene(scene, tessellation, Workers(settings.threads));
}

// The accumulation buffer's passes: where in the pixel, where on the lens
// and when in the shutter interval each is taken, every dimension stratified
// on its own and shuffled, as the distributed ray tracer's samples are
// (core/sampler.hpp). The offsets follow the render's sample pattern, the same in every
// pixel; adaptive refinement needs a pixel of its own to refine, which a
// whole-frame pass is not, so it takes jittered offsets. A camera without a
// shutter interval takes every pass at its opening.
std::vector<AccumulationPass> accumulationPasses(const Camera& camera,
                                                 const RenderSettings& settings) {
  const PixelSampling& sampling = settings.sampling;
  const SamplePattern pattern =
      sampling.pattern == SamplePattern::Adaptive ? SamplePattern::Jittered : sampling.pattern;
  Rng rng(settings.seed);
  Sampler sampler({.squares = 1, .intervals = 1});  // the lens, the time
  const std::vector<Vec2>& offsets =
      sampler.startPixel({sampling.samples, pattern, sampling.filter}, rng);
  std::vector<AccumulationPass> passes;
  for (int i = 0; i < sampling.samples; ++i) {
    SampleValues values = sampler.valuesOf(i, rng);
    const Vec2 lens = values.next2D();
    passes.push_back(
        {offsets[static_cast<std::size_t>(i)], lens, camera.sceneTime(values.next1D())});
  }
  return passes;
}

namespace {

// Reports the progress of a group of passes as its share of all of them;
// the steps of the first pass alone are recorded, the others repeating them.
class PassGroupObserver final : public RenderObserver {
 public:
  PassGroupObserver(RenderObserver& whole, int firstPass, int groupPasses, int passes)
      : whole_(whole), firstPass_(firstPass), groupPasses_(groupPasses), passes_(passes) {}
  void onProgress(double fractionDone) override {
    whole_.onProgress((firstPass_ + fractionDone * groupPasses_) / passes_);
  }
  bool cancelled() const override { return whole_.cancelled(); }
  StepRecorder* stepRecorder() override {
    return firstPass_ == 0 ? whole_.stepRecorder() : nullptr;
  }
  void onPixelsDone(const PixelRect& region, const Image& image) override {
    whole_.onPixelsDone(region, image);
  }

 private:
  RenderObserver& whole_;
  int firstPass_;
  int groupPasses_;
  int passes_;
};

// Tells the render's observer of the frame's pixels in each region the
// algorithm finishes; of the whole frame at the end when the algorithm's
// work is not cut into regions of the image (Warnock's windows are handed out
// as they are made).
class FrameRegions final : public Progress {
 public:
  FrameRegions(RenderObserver& observer, const RasterFrame& frame)
      : observer_(observer), frame_(frame) {}
  ~FrameRegions() override {
    if (!reported_ && !observer_.cancelled())
      observer_.onPixelsDone({0, 0, frame_.width(), frame_.height()}, frame_.image());
  }
  void onProgress(double fractionDone) override { observer_.onProgress(fractionDone); }
  bool cancelled() const override { return observer_.cancelled(); }
  void onRegionDone(const PixelRect& region) override {
    reported_ = true;
    observer_.onPixelsDone(region, frame_.image());
  }

 private:
  RenderObserver& observer_;
  const RasterFrame& frame_;
  std::atomic<bool> reported_{false};
};

}  // namespace

RenderResult VisibleSurfaceRenderer::render(const Scene& scene, const RenderSettings& settings,
                                            RenderObserver& observer) const {
  return renderTessellated(scene, settings, observer, sceneTessellator(scene, settings));
}

RenderResult VisibleSurfaceRenderer::renderTessellated(const Scene& scene,
                                                       const RenderSettings& settings,
                                                       RenderObserver& observer,
                                                       const Tessellator& tessellate) const {
  return renderInPasses(
      scene, settings, observer,
      [&](const TessellatedScene& tessellated, const ScreenGeometry& screen,
          const AccumulationPass& pass, RenderObserver& passObserver) {
        return renderProjected(scene, tessellated, screen, settings, pass, passObserver);
      },
      tessellate);
}

Tessellator sceneTessellator(const Scene& scene, const RenderSettings& settings) {
  return [&scene, &settings](float time) { return tessellateForRaster(scene, settings, time); };
}

// Each pass's pixels go to the film as samples at the pass's offset, so
// that the reconstruction filter weighs them as it weighs the ray tracers'
// samples. The scene is tessellated again only when a pass's time
// differs from the last. The auxiliary buffers are the first pass's, but
// "cost", which adds up over the passes where it is wanted, as do the counters.
RenderResult renderInPassGroups(const Scene& scene, const RenderSettings& settings,
                                RenderObserver& observer, int largestGroup,
                                const PassGroupRenderer& renderGroup,
                                const Tessellator& tessellate) {
  const std::vector<AccumulationPass> passes = accumulationPasses(scene.camera, settings);
  const int passCount = static_cast<int>(passes.size());
  TessellatedScene tessellated = tessellate(passes[0].time);
  Film film(settings.width, settings.height, settings.sampling.filter);
  const Workers workers(settings.threads);
  const ViewFrame frame(scene.camera, settings.width, settings.height);
  PassProjections projections(frame, passes, settings.backfaceCulling, workers);

  RenderResult accumulated;
  for (int first = 0; first < passCount && !observer.cancelled();) {
    if (first > 0 && passes[first].time != passes[first - 1].time)
      tessellated = tessellate(passes[first].time);
    int end = first + 1;
    while (end < passCount && end - first < largestGroup && passes[end].time == passes[first].time)
      ++end;
    const std::span<const AccumulationPass> group(passes.begin() + first, passes.begin() + end);
    PassGroupObserver groupObserver(observer, first, end - first, passCount);
    std::vector<RenderResult> results =
        renderGroup(tessellated, group, first, projections, film, groupObserver);
    for (int pass = first; pass < end; ++pass) {
      RenderResult& result = results[static_cast<std::size_t>(pass - first)];
      if (pass == 0) {
        accumulated = std::move(result);
        continue;
      }
      accumulated.stats.accumulate(result.stats);
      if (Image* cost = accumulated.buffer("cost")) {
        const Image& passCost = result.buffers.at("cost");
        for (int y = 0; y < settings.height; ++y)
          for (int x = 0; x < settings.width; ++x) cost->at(x, y) += passCost.at(x, y);
      }
    }
    first = end;
  }
  accumulated.image = film.resolve(workers);
  // A frame is drawn whole, each polygon at once: a region is cut from it.
  cropToRegion(accumulated, settings);
  const double covered = accumulated.stats.value("covered_pixels");
  accumulated.stats.add("overdraw",
                        covered > 0.0 ? accumulated.stats.value("pixels_written") / covered : 0.0);
  accumulated.stats.add("samples_per_pixel", passCount);
  return accumulated;
}

RenderResult renderInPasses(const Scene& scene, const RenderSettings& settings,
                            RenderObserver& observer, const PassRenderer& renderPass,
                            const Tessellator& tessellate) {
  return renderInPassGroups(
      scene, settings, observer, 1,
      [&](const TessellatedScene& tessellated, std::span<const AccumulationPass> passes,
          int firstPass, PassProjections& projections, Film& film, RenderObserver& passObserver) {
        const ScreenGeometry screen = projections.of(firstPass, tessellated);
        std::vector<RenderResult> results;
        results.push_back(renderPass(tessellated, screen, passes[0], passObserver));
        film.addImage(std::move(results.back().image), passes[0].pixelOffset,
                      Workers(settings.threads));
        return results;
      },
      tessellate);
}

ScreenGeometry PassProjections::of(int pass, const TessellatedScene& tessellated) {
  const ViewProjection view = viewOf(pass);
  if (keptFor_ < 0 || !seeFromTheSamePoint(keptFor_, pass))
    unshifted_ = projectUnshifted(tessellated, view, backfaceCulling_, workers_);
  // Kept for the next pass where it shares the point of the lens, else
  // handed over.
  ScreenGeometry screen;
  if (pass + 1 < static_cast<int>(passes_.size()) && seeFromTheSamePoint(pass, pass + 1)) {
    screen = unshifted_;
    keptFor_ = pass;
  } else {
    screen = std::move(unshifted_);
    keptFor_ = -1;
  }
  moveBy(screen, view.shift(), workers_);
  return screen;
}

ViewProjection PassProjections::viewOf(int pass) const {
  const AccumulationPass& of = passes_[static_cast<std::size_t>(pass)];
  return ViewProjection(frame_, of.pixelOffset, of.lens);
}

bool PassProjections::seeFromTheSamePoint(int pass, int other) const {
  const AccumulationPass& a = passes_[static_cast<std::size_t>(pass)];
  const AccumulationPass& b = passes_[static_cast<std::size_t>(other)];
  return a.time == b.time && frame_.lensPoint(a.lens) == frame_.lensPoint(b.lens);
}

RenderResult VisibleSurfaceRenderer::renderSample(const Scene& scene,
                                                  const TessellatedScene& tessellated,
                                                  const RenderSettings& settings,
                                                  const AccumulationPass& pass,
                                                  RenderObserver& observer) const {
  const ViewProjection view(ViewFrame(scene.camera, settings.width, settings.height),
                            pass.pixelOffset, pass.lens);
  const ScreenGeometry screen = projectScene(tessellated, view, settings.backfaceCulling,
                                             Workers(settings.threads, observer));
  return renderProjected(scene, tessellated, screen, settings, pass, observer);
}

RenderResult VisibleSurfaceRenderer::renderProjected(
    const Scene& scene, const TessellatedScene& tessellated, const ScreenGeometry& screen,
    const RenderSettings& settings, const AccumulationPass& pass, RenderObserver& observer) const {
  const Workers workers(settings.threads, observer);
  const ViewProjection view(ViewFrame(scene.camera, settings.width, settings.height),
                            pass.pixelOffset, pass.lens);
  std::optional<ShadowMaps> shadowMaps;
  const double shadowMapSeconds = secondsOf([&] {
    if (settings.shadows == ShadowMethod::Map)
      shadowMaps.emplace(scene, tessellated, shadowMapSettings(settings), workers);
  });
  std::optional<ShadowVolumes> shadowVolumes;
  const double shadowVolumeSeconds = secondsOf([&] {
    if (settings.shadows == ShadowMethod::Volume && description().draws(ShadowMethod::Volume))
      shadowVolumes.emplace(scene, tessellated, view, workers);
  });
  std::optional<SurfaceShader> shader;
  // Gouraud's and flat shading light the vertices and faces before drawing.
  const double lightingSeconds = secondsOf([&] {
    shader.emplace(scene, tessellated, screen, view, settings.shading, workers,
                   shadowMaps ? &*shadowMaps : nullptr);
  });
  RasterFrame frame(settings, scene.image.background, screen, *shader, workers,
                    observer.stepRecorder(), shadowVolumes ? &*shadowVolumes : nullptr);

  Stats stats;
  addProjectionStats(stats, screen);
  const std::clock_t drawingStart = std::clock();
  const double drawingSeconds = secondsOf([&] {
    FrameRegions regions(observer, frame);
    resolveVisibility(screen, settings, Workers(settings.threads, regions), frame, stats);
  });
  const double drawingThreadSeconds =
      static_cast<double>(std::clock() - drawingStart) / CLOCKS_PER_SEC;
  stats.add("covered_pixels", static_cast<double>(frame.coveredPixels()));
  // Shading happens as the algorithm writes each pixel, on every thread: its
  // share of all the threads' time drawing, estimated from the pixels the
  // frame timed, is its share of the drawing's time.
  const double shadingShare =
      drawingThreadSeconds > 0.0
          ? std::min(frame.shadingSecondsEstimate() / drawingThreadSeconds, 1.0)
          : 0.0;
  const double shadingSeconds = shadingShare * drawingSeconds;
  stats.add("visible_surface_seconds", drawingSeconds - shadingSeconds);
  stats.add("shading_seconds", lightingSeconds + shadingSeconds);

  RenderResult result = frame.takeResult();
  if (shadowMaps) {
    shadowMaps->addStats(stats);
    stats.add("shadow_map_seconds", shadowMapSeconds);
    result.buffers["shadow-map"] = shadowMaps->picture();
  }
  if (shadowVolumes) {
    shadowVolumes->addStats(stats);
    stats.add("shadow_volume_seconds", shadowVolumeSeconds);
  }
  result.stats = std::move(stats);
  return result;
}

}  // namespace rise
