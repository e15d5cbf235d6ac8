// What the four visible-surface algorithms (depth sort, area subdivision,
// z-buffer, scanline) share: each answers one question, which face is visible
// at each pixel, and everything around that answer is common to them.
//
//   tessellate   every shape into triangles in the world (Shape::tessellate)
//   project      cull, clip and project them (ScreenGeometry)
//   resolve      the algorithm: the face seen at each pixel centre
//   shade        that face at that pixel, flat, Gouraud or Phong (SurfaceShader)
//
// The statistics count the polygons at each step (in, culled, outside the
// view, clipped, drawn), then what the algorithm did; "pixels_written" counts
// every time a pixel's face was set, and "overdraw" divides it by
// "covered_pixels", the pixels some face is seen at. With several samples a
// pixel, every pass is counted. The "cost" buffer holds, at each pixel, the work the
// algorithm spent on it, in the units its description gives.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "raster/raster_frame.hpp"
#include "raster/tessellated_scene.hpp"
#include "render/film.hpp"

namespace rise {

// One image of the accumulation buffer: each pixel (i, j) shows the scene at
// the raster position (i + pixelOffset.x, j + pixelOffset.y), seen from the
// point of the lens that `lens` picks (ViewProjection), at the fraction
// `time` of the shutter interval. The defaults are a pinhole image of pixel
// centres at the shutter's opening.
struct AccumulationPass {
  Vec2 pixelOffset{0.5f};
  Vec2 lens{0.5f};
  float time = 0.0f;
};

// Averaging images taken over offsets spread across the pixel anti-aliases
// them; over points spread across the lens, it blurs what is out of focus;
// over instants spread across the shutter interval, what moves (P. Haeberli
// and K. Akeley, "The accumulation buffer: hardware support for high-quality
// rendering", SIGGRAPH 1990). Each pass is a whole image by the algorithm.
// The scene's triangles at a fraction of the shutter interval: the scene
// tessellated (tessellateForRaster), or a mesh made from it, such as
// radiosity's elements with the light solved at their vertices.
using Tessellator = std::function<TessellatedScene(float time)>;

class VisibleSurfaceRenderer : public Renderer {
 public:
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
  // The same, of the triangles `tessellate` gives.
  RenderResult renderTessellated(const Scene& scene, const RenderSettings& settings,
                                 RenderObserver& observer, const Tessellator& tessellate) const;

  // One pass, of the scene tessellated at the pass's time.
  RenderResult renderSample(const Scene& scene, const TessellatedScene& tessellated,
                            const RenderSettings& settings, const AccumulationPass& pass,
                            RenderObserver& observer) const;
  // The same, of the scene as the pass sees it projected (projectScene).
  RenderResult renderProjected(const Scene& scene, const TessellatedScene& tessellated,
                               const ScreenGeometry& screen, const RenderSettings& settings,
                               const AccumulationPass& pass, RenderObserver& observer) const;

 protected:
  // Finds the face seen at each pixel and tells the frame, adding the
  // algorithm's counters to `stats`, among them "pixels_written"; of the
  // settings, it reads those its description's options name. The workers
  // report progress to the render's observer.
  virtual void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                                 const Workers& workers, RasterFrame& frame,
                                 Stats& stats) const = 0;
};

// The passes the settings' samples call for, each dimension stratified and
// shuffled apart.
std::vector<AccumulationPass> accumulationPasses(const Camera& camera,
                                                 const RenderSettings& settings);

// The scene as each pass of a render sees it, projected (projectScene). The
// projection from a point of the lens is made once for the consecutive
// passes that see the scene from there at one instant: each pass's is it,
// moved by the pass's shift in the pixel. Without depth of field and motion
// blur, that is once for all the passes.
class PassProjections {
 public:
  PassProjections(const ViewFrame& frame, std::span<const AccumulationPass> passes,
                  bool backfaceCulling, const Workers& workers)
      : frame_(frame), passes_(passes), backfaceCulling_(backfaceCulling), workers_(workers) {}

  // Pass number `pass`'s projection of the scene tessellated at its instant,
  // the passes asked for in their order.
  ScreenGeometry of(int pass, const TessellatedScene& tessellated);

 private:
  ViewProjection viewOf(int pass) const;
  bool seeFromTheSamePoint(int pass, int other) const;

  const ViewFrame& frame_;
  std::span<const AccumulationPass> passes_;
  bool backfaceCulling_;
  const Workers& workers_;
  ScreenGeometry unshifted_;  // the projection from pass keptFor_'s point of the lens
  int keptFor_ = -1;          // -1: none kept
};

// Renders one pass, of the scene tessellated at the pass's time and projected
// as the pass sees it: the image with the auxiliary buffers the settings
// want, and the counters.
using PassRenderer =
    std::function<RenderResult(const TessellatedScene& tessellated, const ScreenGeometry& screen,
                               const AccumulationPass& pass, RenderObserver& observer)>;

// The accumulation buffer: the passes the settings' samples call for, each
// rendered by `renderPass` and added to the film through the reconstruction
// filter. What every visible-surface algorithm renders by.
RenderResult renderInPasses(const Scene& scene, const RenderSettings& settings,
                            RenderObserver& observer, const PassRenderer& renderPass,
                            const Tessellator& tessellate);

// Renders a group of consecutive passes that share an instant, all of the
// scene tessellated then, the first of them pass number `firstPass`: for
// each, in order, what a PassRenderer renders, its projection asked of
// `projections`, but that the passes' samples go to `film` rather than into
// their results' images. The observer reports the group's progress; it
// records steps only in the group that holds pass 0, whose steps alone are to
// be recorded.
using PassGroupRenderer = std::function<std::vector<RenderResult>(
    const TessellatedScene& tessellated, std::span<const AccumulationPass> passes, int firstPass,
    PassProjections& projections, Film& film, RenderObserver& observer)>;

// renderInPasses, the passes taken in groups of at most `largestGroup`, for
// an algorithm that does better with several passes in hand at once: the
// hybrid algorithm shades a pixel's samples one after another.
RenderResult renderInPassGroups(const Scene& scene, const RenderSettings& settings,
                                RenderObserver& observer, int largestGroup,
                                const PassGroupRenderer& renderGroup,
                                const Tessellator& tessellate);

// The scene tessellated by tessellateForRaster, as the settings ask.
Tessellator sceneTessellator(const Scene& scene, const RenderSettings& settings);

// "polygons_in", "polygons_culled", ...: what the projection did.
void addProjectionStats(Stats& stats, const ScreenGeometry& screen);

// The description of a visible-surface algorithm: what the family shares
// (its buffers, the settings it reads, the effects of the accumulation
// passes and of shadow maps) with the algorithm's own name, summary,
// citation, effects, settings and ways of drawing shadows.
AlgorithmDescription visibleSurfaceAlgorithm(std::string_view name, std::string_view summary,
                                             std::string_view citation,
                                             std::vector<Effect> ownEffects = {},
                                             std::vector<Option> ownOptions = {},
                                             std::vector<ShadowMethod> ownShadowMethods = {});

// What a render by any of them needs: each pass's images and frame, the
// film's sums, the polygons on the screen.
RenderNeeds visibleSurfaceNeeds(const Scene& scene, const RenderSettings& settings);

// The scene tessellated as the settings ask, planes centred under the camera,
// moving shapes where they are at `time`, a fraction of the shutter interval
// (0, its opening, by default, as Whitted's ray tracer sees the scene).
TessellatedScene tessellateForRaster(const Scene& scene, const RenderSettings& settings,
                                     float time = 0.0f);

}  // namespace rise
