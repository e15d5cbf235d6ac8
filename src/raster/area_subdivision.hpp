// Area subdivision (J. E. Warnock, "A hidden-surface algorithm for computer
// generated half-tone pictures", University of Utah, technical report
// TR 4-15, 1969).
//
// Divide and conquer over the screen: a window, at first the whole image, is
// drawn at once if what it shows is simple; otherwise it is cut into four
// quadrants, each handled the same way. Each polygon stands to a window in
// one of four relations:
//   surrounding   it holds the whole window;
//   intersecting  it crosses the window's border;
//   contained     it lies wholly inside the window;
//   disjoint      it covers none of it.
// A window is simple, and drawn, when
//   - every polygon is disjoint from it: it shows the background;
//   - one polygon alone is not disjoint: it is scan-converted in the window
//     over the background;
//   - a surrounding polygon is in front of all the others everywhere in the
//     window (its farthest depth there nearer than their nearest): it fills
//     the window;
//   - the window is a single pixel: the polygons covering the pixel's centre
//     are compared in depth there, and the nearest is drawn.
// Only the polygons not disjoint from a window are handed to its quadrants.
//
// Depths are inverse depths w = 1 / n, affine across a polygon's image, so
// their extremes over a window lie at its corners. The windows three levels
// down are shared among threads, each subdividing its own. Cost of a pixel:
// the classifications made for the windows that hold it, each window's shared
// among its pixels, plus the depth tests made at the pixel.
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class AreaSubdivisionRenderer final : public VisibleSurfaceRenderer {
 public:
  std::string_view name() const override { return "area-subdivision"; }
  std::string_view summary() const override {
    return "Warnock's area subdivision: quarter the screen until each window is simple";
  }
  std::string_view citation() const override {
    return "J. E. Warnock, A hidden-surface algorithm for computer generated half-tone pictures, "
           "University of Utah, TR 4-15, 1969";
  }

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         RenderObserver& observer, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
