// The z-buffer (E. Catmull, "A subdivision algorithm for computer display of
// curved surfaces", PhD thesis, University of Utah, 1974).
//
// Beside the image, a buffer holds the depth of what each pixel shows, all
// pixels starting infinitely far. The polygons are drawn one by one, in any
// order: at each pixel centre a polygon covers (by the top-left fill rule,
// so that a pixel on an edge two polygons share is drawn by one of them),
// its depth is compared with the buffer's, and if nearer it takes the pixel
// and the buffer takes its depth. Nothing is sorted and no two polygons are
// ever compared; the price is memory, a depth and a face for every pixel of
// the image (reported as "z_buffer_bytes"), and the work spent on hidden
// polygons ("overdraw").
//
// Depths are compared as w = 1 / n, which is affine across a polygon's image
// and larger for nearer points. The image is cut into bands of scanlines that
// threads draw in parallel, each band with the polygons that reach into it.
// Cost of a pixel: the depth tests made at it.
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class ZBufferRenderer final : public VisibleSurfaceRenderer {
 public:
  std::string_view name() const override { return "z-buffer"; }
  std::string_view summary() const override {
    return "Catmull's z-buffer: a depth per pixel, polygons drawn in any order";
  }
  std::string_view citation() const override {
    return "E. Catmull, A subdivision algorithm for computer display of curved surfaces, "
           "PhD thesis, University of Utah, 1974";
  }

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         RenderObserver& observer, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
