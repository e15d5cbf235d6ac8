// Path tracing (path_tracing.cpp tells it).
#pragma once

#include "ray/ray_tracer.hpp"

namespace rise {

class PathTracer final : public RayTracer {
 public:
  const AlgorithmDescription& description() const override;
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
