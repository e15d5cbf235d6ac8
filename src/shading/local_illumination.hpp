// The Phong model summed over the lights: the light a point receives when
// nothing but its own surface stands between it and a light, or, given a
// LightVisibility, when the shadows it answers do. The visible-surface
// algorithms compute it so; where they evaluate it makes their three shading
// methods:
//
//   flat     once per face, at its centroid with its own normal
//            (W. J. Bouknight, "A procedure for generation of
//            three-dimensional half-toned computer graphics presentations",
//            CACM 13(9), 1970)
//   gouraud  at the vertices with their normals, the colours then
//            interpolated (H. Gouraud, "Continuous shading of curved
//            surfaces", IEEE Transactions on Computers 20(6), 1971)
//   phong    at every pixel, with the normal interpolated (B. T. Phong,
//            "Illumination for computer generated pictures", CACM 18(6), 1975)
//
// A texture's colour C, and a ks texture's ks, are looked up at every pixel
// whatever the shading: flat and Gouraud keep apart the part of the model that
// C multiplies (ambient and diffuse) and the part that ks multiplies (the
// highlight), as OpenGL's separate specular colour does, and combine them with
// C and ks at the pixel (raster/surface_shader.hpp).
#pragma once

#include "scene/scene.hpp"
#include "shading/light_visibility.hpp"
#include "shading/material_at_point.hpp"

namespace rise {

// The model's light at `position`, seen from `eye`, on a surface whose own
// normal there is `surfaceNormal`, shaded with `shadingNormal` (tilted by a
// bump or normal map), both on the side the eye sees. A light behind the
// surface is hidden by it, however far the shading normal tilts; one in front
// reaches it as `shadows` says, wholly when it is null.
Color localLight(const Scene& scene, const Material& material, const SurfaceColors& colors,
                 const Vec3& position, const Vec3& surfaceNormal, const Vec3& shadingNormal,
                 const Vec3& eye, const LightVisibility* shadows = nullptr);

// The same light as C * byColor + ks * byKs + emitted: the model is linear
// in C and ks.
struct SplitLight {
  Color byColor{0.0f};
  Color byKs{0.0f};
  Color emitted{0.0f};

  Color with(const SurfaceColors& colors) const {
    return colors.color * byColor + colors.ks * byKs + emitted;
  }
};

SplitLight splitLocalLight(const Scene& scene, const Material& material, const Vec3& position,
                           const Vec3& normal, const Vec3& eye,
                           const LightVisibility* shadows = nullptr);

}  // namespace rise
