// What every ray tracer does at the surface a ray hits before it shades it,
// and as it leaves it: the surface seen from the ray's side, and rays
// spawned from there that do not hit the surface they leave.
#pragma once

#include "core/ray.hpp"
#include "scene/material.hpp"
#include "scene/shape.hpp"

namespace rise {

// The surface at a hit as the shading sees it: the normal turned towards the
// side the ray came from, and whether the ray is entering the solid.
struct ShadingFrame {
  SurfacePoint surface;
  Vec3 normal{0.0f};         // the geometric normal, unit, on the ray's side of the surface
  Vec3 shadingNormal{0.0f};  // the smooth normal for shading, on the same side
  Vec3 toViewer{0.0f};       // unit, back along the ray
  float time = 0.0f;         // the ray's instant, which the rays it spawns keep
  bool entering = false;
};

// The frame at the ray's hit on a surface of `material`: its texture frame
// too where the material's maps read it, its shading normal bumped or
// mapped as the material says.
ShadingFrame shadingFrame(const Ray& ray, const Hit& hit, const Material& material);

// A ray leaving the surface along `direction`, started a little off the
// surface on the side it travels to, so that it does not hit it again.
Ray spawnRay(const ShadingFrame& frame, const Vec3& direction);

}  // namespace rise
