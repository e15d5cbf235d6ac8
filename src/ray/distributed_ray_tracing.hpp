// Distributed ray tracing (distributed_ray_tracing.cpp tells it).
#pragma once

#include "render/renderer.hpp"

namespace rise {

class DistributedRayTracer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

// The ray through the raster position from the point of a thin lens that
// `lens` picks (ViewFrame::lensPoint), aimed at the point the pinhole ray
// meets on the plane in focus; the pinhole ray itself with no aperture.
Ray thinLensRay(const ViewFrame& view, const Vec2& raster, const Vec2& lens);

}  // namespace rise
