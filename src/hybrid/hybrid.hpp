// The hybrid scan-line / ray-tracing algorithm (hybrid.cpp tells it).
#pragma once

#include "render/renderer.hpp"

namespace rise {

class HybridRenderer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
