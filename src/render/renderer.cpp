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

std::string_view toString(Option option) {
  switch (option) {
    case Option::Shading:
      return "shading";
    case Option::Culling:
      return "no-cull";
    case Option::Tessellation:
      return "tessellation";
    case Option::PlaneSize:
      return "plane-size";
    case Option::Shadows:
      return "shadows";
    case Option::Transparency:
      return "transparency";
    case Option::Accel:
      return "accel";
    case Option::MaxDepth:
      return "max-depth";
    case Option::LightSampling:
      return "light-sampling";
    case Option::Progression:
      return "time-limit";
    case Option::Radiosity:
      return "patch-size";
  }
  return "?";
}

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
