// The z-buffer algorithm (z_buffer.cpp tells it).
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class ZBufferRenderer final : public VisibleSurfaceRenderer {
 public:
  const AlgorithmDescription& description() const override;

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         const Workers& workers, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
