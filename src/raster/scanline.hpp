// Scanline (scanline.cpp tells it).
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class ScanlineRenderer final : public VisibleSurfaceRenderer {
 public:
  const AlgorithmDescription& description() const override;

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         const Workers& workers, RasterFrame& frame, Stats& stats) const override;
};

// The sweep alone: tells `faces` the nearest face at every pixel centre,
// transparent or not, and the depth tests made there, and adds the sweep's
// counters to `stats`. The hybrid algorithm fills its item buffer with it.
void sweepScanlines(const ScreenGeometry& screen, const Workers& workers, VisibleFaces& faces,
                    Stats& stats);

}  // namespace rise
