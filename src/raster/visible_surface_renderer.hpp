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

#include "raster/raster_frame.hpp"
#include "raster/tessellated_scene.hpp"

namespace rise {

class VisibleSurfaceRenderer : public Renderer {
 public:
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;

  // One image of a tessellated scene, each pixel (i, j) showing the scene at
  // the raster position (i + sampleOffset.x, j + sampleOffset.y). Averaging
  // such images over offsets spread across the pixel anti-aliases them, as an
  // accumulation buffer does (P. Haeberli and K. Akeley, "The accumulation
  // buffer: hardware support for high-quality rendering", SIGGRAPH 1990).
  RenderResult renderSample(const Scene& scene, const TessellatedScene& tessellated,
                            const RenderSettings& settings, Vec2 sampleOffset,
                            RenderObserver& observer) const;

 protected:
  // Finds the face seen at each pixel and tells the frame, adding the
  // algorithm's counters to `stats`, among them "pixels_written".
  virtual void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                                 RenderObserver& observer, RasterFrame& frame,
                                 Stats& stats) const = 0;
};

// The scene tessellated as the settings ask, planes centred under the camera,
// moving shapes where they are when the shutter opens.
TessellatedScene tessellateForRaster(const Scene& scene, const RenderSettings& settings);

}  // namespace rise
