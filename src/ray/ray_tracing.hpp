// Whitted ray tracing (T. Whitted, "An improved illumination model for shaded
// display", CACM 23(6), 1980), as in the original RISE report.
//
// One ray leaves a pinhole eye through each sample position of a pixel and
// is traced recursively (see recursive_tracer.hpp): shadows, mirror
// reflection, refraction. The scene is seen at one instant, the shutter's
// opening; area lights act as points at their centres and rough materials as
// smooth ones. Anti-aliasing comes from several samples in each pixel,
// placed by the render's sample pattern.
#pragma once

#include "render/renderer.hpp"

namespace rise {

class WhittedRayTracer final : public Renderer {
 public:
  std::string_view name() const override { return "ray-tracing"; }
  std::string_view summary() const override {
    return "Whitted ray tracing: shadows, mirror reflection and refraction, recursively";
  }
  std::string_view citation() const override {
    return "T. Whitted, An improved illumination model for shaded display, CACM 23(6), 1980";
  }

  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

}  // namespace rise
