// Distributed ray tracing (R. L. Cook, T. Porter and L. Carpenter,
// "Distributed ray tracing", SIGGRAPH 1984).
//
// Whitted's ray tracer takes one ray for each choice that light could make;
// Cook's insight is that the fuzzy phenomena of real images are averages
// over those choices, and that the rays a pixel already needs for
// anti-aliasing can sample them at no extra cost: each of the pixel's rays
// leaves from its own point of a thin lens (depth of field), at its own
// instant of the shutter interval (motion blur), aims its shadow rays at its
// own point of each area light (soft shadows), and spreads its reflected and
// refracted rays around the ideal directions by the material's roughness
// (gloss and translucency). The samples of each dimension are stratified and
// shuffled independently (see image_sampler.hpp), so that a few of them
// cover every dimension at once.
#pragma once

#include "render/renderer.hpp"

namespace rise {

class DistributedRayTracer final : public Renderer {
 public:
  std::string_view name() const override { return "distributed-ray-tracing"; }
  std::string_view summary() const override {
    return "Cook's distributed ray tracing: depth of field, motion blur, soft shadows, gloss";
  }
  std::string_view citation() const override {
    return "R. L. Cook, T. Porter, L. Carpenter, Distributed ray tracing, SIGGRAPH 1984";
  }

  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
