#include "render/renderer.hpp"

#include <algorithm>

namespace rise {

std::string_view toString(Family family) {
  switch (family) {
    case Family::VisibleSurface:
      return "visible surface";
    case Family::RayTracing:
      return "ray tracing";
    case Family::Hybrid:
      return "hybrid";
    case Family::Radiosity:
      return "radiosity";
  }
  return "?";
}

std::span<const std::string_view> flagsOf(Option option) {
  static constexpr std::string_view kShading[] = {"shading"}, kCulling[] = {"no-cull"},
                                    kTessellation[] = {"tessellation"},
                                    kPlaneSize[] = {"plane-size"},
                                    kShadows[] = {"shadows", "shadow-map-size", "shadow-bias",
                                                  "shadow-filter"},
                                    kTransparency[] = {"transparency"}, kAccel[] = {"accel"},
                                    kMaxDepth[] = {"max-depth"},
                                    kLightSampling[] = {"light-sampling", "no-roulette"},
                                    kProgression[] = {"time-limit", "noise-target"},
                                    kRadiosity[] = {"patch-size",   "residual",      "solver",
                                                    "form-factors", "hemicube-size", "display"};
  switch (option) {
    case Option::Shading:
      return kShading;
    case Option::Culling:
      return kCulling;
    case Option::Tessellation:
      return kTessellation;
    case Option::PlaneSize:
      return kPlaneSize;
    case Option::Shadows:
      return kShadows;
    case Option::Transparency:
      return kTransparency;
    case Option::Accel:
      return kAccel;
    case Option::MaxDepth:
      return kMaxDepth;
    case Option::LightSampling:
      return kLightSampling;
    case Option::Progression:
      return kProgression;
    case Option::Radiosity:
      break;
  }
  return kRadiosity;
}

std::string_view toString(Option option) { return flagsOf(option).front(); }

std::string_view toString(Effect effect) {
  switch (effect) {
    case Effect::Shadows:
      return "shadows";
    case Effect::Reflection:
      return "reflection";
    case Effect::Refraction:
      return "refraction";
    case Effect::DepthOfField:
      return "depth of field";
    case Effect::MotionBlur:
      return "motion blur";
    case Effect::SoftShadows:
      return "soft shadows";
    case Effect::Gloss:
      return "gloss";
    case Effect::Transparency:
      return "transparency";
    case Effect::IndirectLight:
      return "indirect light";
  }
  return "?";
}

std::string_view toString(Look look) {
  switch (look) {
    case Look::Steps:
      return "steps";
    case Look::RayTrees:
      return "ray trees";
  }
  return "?";
}

bool AlgorithmDescription::offers(Look look) const {
  return std::find(looks.begin(), looks.end(), look) != looks.end();
}

bool AlgorithmDescription::writes(std::string_view buffer) const {
  return std::find(buffers.begin(), buffers.end(), buffer) != buffers.end();
}

bool AlgorithmDescription::reads(Option option) const {
  return std::find(options.begin(), options.end(), option) != options.end();
}

bool AlgorithmDescription::draws(ShadowMethod method) const {
  return method == ShadowMethod::None ||
         std::find(shadowMethods.begin(), shadowMethods.end(), method) != shadowMethods.end();
}

void cropToRegion(RenderResult& result, const RenderSettings& settings) {
  if (!settings.region) return;
  // A buffer of another size is not of the image's pixels (the shadow map,
  // the light's view) and stays whole.
  for (auto& [name, buffer] : result.buffers)
    if (buffer.width() == result.image.width() && buffer.height() == result.image.height())
      buffer = cropped(buffer, *settings.region);
  result.image = cropped(result.image, *settings.region);
}

}  // namespace rise
