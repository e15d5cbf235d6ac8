// The colour of the surface that a visible-surface algorithm found at a
// pixel: the Phong model without shadows (shading/local_illumination.hpp),
// evaluated once per face (flat), at the vertices (Gouraud) or at the pixel
// (Phong), as the render's settings ask. Interpolation is
// perspective-correct, by the face's barycentric coordinates at the pixel's
// centre in the world (ScreenFace); textures are looked up over the pixel's
// footprint in them (for mipmapping).
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
#include "shading/local_illumination.hpp"

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
  PixelFootprint uvFootprint(int face, const Vec2& centre) const;
  void lightFaces(const Workers& workers);
  void lightVertices(const Workers& workers);

  const Scene& scene_;
  const TessellatedScene& tessellated_;
  const ScreenGeometry& screen_;
  Vec3 eye_;
  Shading shading_;
  std::vector<SplitLight> faceLight_;  // flat: by screen face
  // Gouraud: by scene vertex, for each side of the surface seen (front:
  // the side its normal points to).
  std::array<std::vector<SplitLight>, 2> vertexLight_;
};

}  // namespace rise
