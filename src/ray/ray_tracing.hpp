// Whitted ray tracing (T. Whitted, "An improved illumination model for shaded
// display", CACM 23(6), 1980), as in the original RISE report's Intersect and
// Shade routines.
//
// A ray leaves the eye through each pixel and finds the nearest surface. There
// the Phong model sums the ambient light and each light that a shadow ray
// finds unblocked; then two new rays carry on recursively: the mirror
// reflection, weighted by the material's `reflection`, and the ray refracted
// by Snell's law, weighted by its `transmission` and tinted by its colour
// (when the angle is past the critical one, total internal reflection sends it
// along the mirror direction instead). Rays that hit nothing take the
// background colour; recursion stops at the settings' maximum depth.
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
