// Distributed ray tracing (distributed_ray_tracing.cpp tells it).
#pragma once

#include "ray/ray_tracer.hpp"

namespace rise {

class DistributedRayTracer final : public RayTracer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
