// The colour of the surface that a visible-surface algorithm found at a
// pixel, by the same Phong illumination model as the ray tracer
// (shading/phong.hpp), evaluated
//
//   flat     once per face, at its centroid with its own normal
//            (W. J. Bouknight, "A procedure for generation of
//            three-dimensional half-toned computer graphics presentations",
//            CACM 13(9), 1970)
//   gouraud  at its three vertices with their normals, the colours then
//            interpolated (H. Gouraud, "Continuous shading of curved
//            surfaces", IEEE Transactions on Computers 20(6), 1971)
//   phong    at every pixel, with the normal interpolated (B. T. Phong,
//            "Illumination for computer generated pictures", CACM 18(6), 1975)
//
// Interpolation is perspective-correct, by the face's barycentric
// coordinates at the pixel's centre in the world (ScreenFace). A texture's
// colour C is looked up at every pixel whatever the shading, over the
// pixel's footprint in the texture (for mipmapping), and so is a ks
// texture's ks: flat and Gouraud keep apart the part of the model that C
// multiplies (ambient and diffuse) and the part that ks multiplies (the
// highlight), as OpenGL's separate specular colour does, and combine them
// with C and ks at the pixel.
//
// What the ray tracer adds to the model is left out: there are no shadows
// (every light reaches every surface facing it), and no mirror reflection or
// refraction; a transparent material is drawn opaque, with the model's
// (1 - t) dimming of its ambient and diffuse light.
#pragma once

#include <array>
#include <vector>

#include "raster/screen_geometry.hpp"
#include "render/renderer.hpp"

namespace rise {

// What is seen at a pixel: its colour, and for the auxiliary buffers the
// distance from the eye and the surface's normal there.
struct ShadedPixel {
  Color color;
  float depth;
  Vec3 normal;
};

class SurfaceShader {
 public:
  // Evaluates the model once per face (flat) or per vertex (Gouraud), on
  // the workers.
  SurfaceShader(const Scene& scene, const TessellatedScene& tessellated,
                const ScreenGeometry& screen, const ViewProjection& view, Shading shading,
                const Workers& workers);

  // The screen face `face` seen at the raster point `centre`.
  ShadedPixel shade(int face, const Vec2& centre) const;

 private:
  // The model's light at a point as C * byColor + ks * byKs.
  struct Illumination {
    Color byColor{0.0f};
    Color byKs{0.0f};

    Color with(const SurfaceColors& colors) const {
      return colors.color * byColor + colors.ks * byKs;
    }
  };

  PixelFootprint uvFootprint(int face, const Vec2& centre) const;
  // The model's light at a point of the surface whose own normal there is
  // `surfaceNormal`, shaded with `shadingNormal` (tilted by a bump or
  // normal map), both on the side the eye sees.
  Color illuminate(const Material& material, const SurfaceColors& colors, const Vec3& position,
                   const Vec3& surfaceNormal, const Vec3& shadingNormal) const;
  Illumination illumination(const Material& material, const Vec3& position,
                            const Vec3& normal) const;
  void lightFaces(const Workers& workers);
  void lightVertices(const Workers& workers);

  const Scene& scene_;
  const TessellatedScene& tessellated_;
  const ScreenGeometry& screen_;
  Vec3 eye_;
  Shading shading_;
  std::vector<Illumination> faceLight_;  // flat: by screen face
  // Gouraud: by scene vertex, for each side of the surface seen (front:
  // the side its normal points to).
  std::array<std::vector<Illumination>, 2> vertexLight_;
};

}  // namespace rise
