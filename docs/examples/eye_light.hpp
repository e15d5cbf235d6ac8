// Eye-light shading (eye_light.cpp tells it): the manual's worked example of
// a new ray tracer.
#pragma once

#include "ray/ray_tracer.hpp"

namespace rise {

class EyeLight final : public RayTracer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
