#pragma once

#include <memory>
#include <string>

#include "core/color.hpp"
#include "scene/textures/bump_map.hpp"
#include "scene/textures/normal_map.hpp"
#include "scene/textures/texture.hpp"

namespace rise {

// The Phong illumination model's surface description, with the textbook's
// names, plus what Whitted's ray tracer adds: mirror reflection and
// transmission through a refracting interior.
struct Material {
  std::string name;
  Color color{1.0f};          // C: the surface colour, for ambient and diffuse light
  float ka = 0.1f;            // ambient coefficient
  float kd = 0.9f;            // diffuse coefficient
  float ks = 0.0f;            // specular coefficient (the highlight has the light's colour)
  float n = 1.0f;             // specular exponent: larger is a smaller, sharper highlight
  float reflection = 0.0f;    // weight of the mirror-reflected ray
  float transmission = 0.0f;  // weight of the refracted ray, tinted by C
  float ior = 1.0f;           // index of refraction of the interior (outside is 1)
  // Gloss and translucency (Cook et al. 1984): how far the distributed ray
  // tracer spreads reflected and refracted rays around their ideal
  // directions, as the tangent of the spread's half-angle. 0 is a perfect
  // mirror or clear glass.
  float roughness = 0.0f;
  // Le: the radiance the surface gives off by itself, on both sides: a lamp's
  // panel or a glowing ball. The path tracer takes it as a light; the other
  // algorithms add it to the surface's colour, as it is whatever the lights.
  Color emission{0.0f};

  std::shared_ptr<const Texture> texture;      // when set, replaces color over the surface
  std::shared_ptr<const BumpMap> bump;         // when set, tilts the shading normal
  std::shared_ptr<const NormalMap> normalMap;  // when set, replaces it, before any bump
  // When set, multiplies ks over the surface, channel by channel: a specular
  // map, shiny where it is bright, matte where it is black.
  std::shared_ptr<const Texture> ksTexture;

  bool isTransparent() const { return transmission > 0.0f; }
  bool emits() const { return emission != Color(0.0f); }
  // Whether shading reads the surface's texture coordinates and tangents:
  // for a texture, or for a map that tilts the normal.
  bool readsTextureFrame() const { return texture || ksTexture || bump || normalMap; }
};

}  // namespace rise
