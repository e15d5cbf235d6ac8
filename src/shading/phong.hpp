// The Phong illumination model (Bui Tuong Phong, "Illumination for
// computer generated pictures", CACM 1975), the one shading model that every
// algorithm in RISE calls:
//
//   I = Le  +  Ia ka C (1 - t)  +  sum over lights  Il (kd C (1 - t) max(0, N.L) + ks max(0,
//   R.V)^n)
//
// Le is the light the surface emits (Material::emission, zero but for a
// lamp), C the surface colour and ks the specular coefficient at the point (a
// texture varies C over the surface, a ks texture ks, channel by channel), t
// the material's transmission (light that passes through a surface is not
// also reflected diffusely), N the unit normal on the viewer's side, L the
// unit direction to the light, V the unit direction to the viewer and R the
// mirror image of L about N. The highlight takes the light's colour (times
// ks), not the surface's, as on plastic. Lights have no fall-off with
// distance. Shadows, mirror reflection and refraction are the ray tracer's
// additions, made outside this model.
#pragma once

#include "core/color.hpp"
#include "scene/light.hpp"
#include "scene/material.hpp"
#include "shading/material_at_point.hpp"

namespace rise {

// The ambient term Ia ka C (1 - t).
Color phongAmbient(const Material& material, const SurfaceColors& surface,
                   const Color& ambientLight);

// What the surface shows whatever the lights: Le + Ia ka C (1 - t).
Color phongUnlit(const Material& material, const SurfaceColors& surface, const Color& ambientLight);

// One light's diffuse and specular terms, given its sample at the surface.
// Zero when the light is behind the surface (N.L <= 0).
Color phongDirect(const Material& material, const SurfaceColors& surface, const Vec3& normal,
                  const Vec3& toViewer, const LightSample& light);

}  // namespace rise
