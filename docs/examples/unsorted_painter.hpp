// The painter's algorithm without its sort (unsorted_painter.cpp tells it):
// the manual's worked example of a new visible-surface algorithm.
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class UnsortedPainter final : public VisibleSurfaceRenderer {
 public:
  const AlgorithmDescription& description() const override;

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         const Workers& workers, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
