// How a surface scatters the light that reaches it, as the path tracer asks:
// a BRDF it evaluates towards a light and samples a direction from. It is the
// Phong model's material made physical, the same keys a student sets for
// every other algorithm:
//   diffuse   kd C (1 - t) / pi: Lambert's law, which Phong's kd C N.L is
//             once the light is measured as radiance;
//   glossy    ks (n + 2) / (2 pi) cos^n(alpha), alpha the angle between the
//             light's direction and the viewer's mirrored about the normal:
//             the modified Phong BRDF (Lafortune and Willems, "Using the
//             modified Phong reflectance model for physically based
//             rendering", 1994), whose factor makes it reflect at most ks
//             of the light, so that it conserves energy and is reciprocal,
//             as Phong's highlight is not;
//   mirror    `reflection` of the light, along the mirror direction alone;
//   glass     `transmission` of the light meets a dielectric interface of
//             index `ior`: Fresnel's equations split it between the mirror
//             direction and the refracted one (tinted by C); past the
//             critical angle all of it reflects.
// Phong's model let kd + ks + reflection + transmission pass 1 (a surface
// brighter than its light); where they do, the four are scaled down
// together, so that no surface returns more light than it receives. `ka` has
// no meaning here: the path tracer computes the light that Phong's ambient
// term stood for.
#pragma once

#include <optional>

#include "core/color.hpp"
#include "core/math.hpp"
#include "scene/material.hpp"
#include "shading/material_at_point.hpp"

namespace rise {

// A direction sampled from the scattering, towards where the light comes
// from. `weight` is f cos / pdf, what the light arriving along it is
// multiplied by; `pdf` is the density per steradian it was chosen with, or,
// for the mirror and the glass (`singular`: one direction alone), the
// probability of choosing that lobe.
struct ScatteringSample {
  Vec3 direction{0.0f};
  Color weight{0.0f};
  float pdf = 0.0f;
  bool singular = false;
  bool refracted = false;
};

// Fresnel's reflectance of unpolarised light at a dielectric interface,
// `cosIncidence` on the side the light comes from, `eta` the index past it
// over the index before it; 1 past the critical angle.
float fresnelDielectric(float cosIncidence, float eta);

class Scattering {
 public:
  // At a surface of `material` with the colours `colors` there, the shading
  // normal on the viewer's side, the unit direction to the viewer, and
  // whether the viewer is outside the solid.
  Scattering(const Material& material, const SurfaceColors& colors, const Vec3& normal,
             const Vec3& toViewer, bool viewerOutside);

  // f(toViewer, toLight) of the diffuse and glossy lobes: the singular ones
  // reach no direction a light is sampled in.
  Color brdf(const Vec3& toLight) const;
  // The density per steradian with which sample() chooses `toLight` by a
  // diffuse or glossy lobe.
  float pdf(const Vec3& toLight) const;
  // A direction chosen by `u` (in the unit square) within a lobe chosen by
  // `choice` (in [0, 1)), each lobe by its share of the light; nothing when
  // the surface scatters no light, or the direction falls below it.
  std::optional<ScatteringSample> sample(const Vec2& u, float choice) const;

  // Whether a lobe spreads light over directions, so that a light sampled
  // at the point may reach the viewer through it.
  bool spreads() const { return diffuseShare_ + glossyShare_ > 0.0f; }

 private:
  Vec3 mirrored(const Vec3& direction) const;
  std::optional<ScatteringSample> sampleGlass(float choice) const;

  Vec3 normal_, toViewer_;
  bool viewerOutside_;
  float ior_, exponent_;
  Color diffuse_, glossy_;  // kd C (1 - t) and ks, scaled
  float reflection_, transmission_;
  Color tint_;  // C, through the glass
  // The probability of choosing each lobe: its largest channel's share.
  float diffuseShare_ = 0.0f, glossyShare_ = 0.0f, mirrorShare_ = 0.0f, glassShare_ = 0.0f;
};

}  // namespace rise
