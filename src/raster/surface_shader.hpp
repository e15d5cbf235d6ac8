// The colour of the surface that a visible-surface algorithm found at a
// pixel: the Phong model without shadows (shading/local_illumination.hpp),
// evaluated once per face (flat), at the vertices (Gouraud) or at the pixel
// (Phong), as the render's settings ask. Interpolation is
// perspective-correct, by the face's barycentric coordinates at the pixel's
// centre in the world (ScreenFace); textures are looked up over the pixel's
// footprint in them (for mipmapping).
//
// Shadows come from `shadows` when it is given (shadow maps), asked where the
// model is evaluated: at every pixel with Phong shading, at the centroid or
// the vertices with flat or Gouraud shading, whose shadows are as coarse as
// their light. Shadow volumes answer for a pixel instead, and a pixel in a
// shadow takes the model evaluated again where the shading evaluates it,
// with those answers: its shadow is as sharp whatever the shading. Without
// either, every light reaches every surface facing it. What else the ray
// tracer adds to the model is left out: no mirror reflection or refraction;
// a transparent material is drawn opaque, with the model's (1 - t) dimming of
// its ambient and diffuse light.
#pragma once

#include <array>
#include <vector>

#include "raster/screen_geometry.hpp"
#include "render/renderer.hpp"
#include "shading/local_illumination.hpp"

namespace rise {

// What is seen at a pixel: its colour, and for the auxiliary buffers the
// distance from the eye and the surface's normal there (PixelGeometry).
struct ShadedPixel {
  Color color;
  float depth;
  Vec3 normal;
};

// Whether a pixel's depth and normal are wanted; when skipped, they are
// left zero, and flat and Gouraud shading of an untextured surface skip
// finding the point of the surface altogether.
enum class PixelGeometry { Wanted, Skipped };

class SurfaceShader {
 public:
  // Evaluates the model once per face (flat) or per vertex (Gouraud), on
  // the workers.
  SurfaceShader(const Scene& scene, const TessellatedScene& tessellated,
                const ScreenGeometry& screen, const ViewProjection& view, Shading shading,
                const Workers& workers, const LightVisibility* shadows = nullptr);

  // The screen face `face` seen at the raster point `centre`; with
  // `pixelShadows`, what reaches the point seen there from each light.
  ShadedPixel shade(int face, const Vec2& centre, const LightVisibility* pixelShadows = nullptr,
                    PixelGeometry geometry = PixelGeometry::Wanted) const;
  const Material& materialOf(int face) const {
    return scene_.materials[tessellated_.faces[screen_.faces[face].sceneFace].material];
  }
  // Whether screen face `face` lets light through; asked of every polygon
  // drawn, and answered at once in a scene where nothing does.
  bool isTransparent(int face) const { return anyTransparent_ && materialOf(face).isTransparent(); }

 private:
  // The point of screen face `face` at barycentric coordinates `weights`,
  // its texture coordinates by the shape's projection where it has one.
  SurfacePoint surfaceAt(int face, const Vec3& weights) const;
  PixelFootprint uvFootprint(int face, const Vec2& centre, const SurfacePoint& surface) const;
  void lightFaces(const Workers& workers);
  void lightVertices(const Workers& workers);
  SplitLight faceLight(int face, const LightVisibility* shadows) const;
  SplitLight vertexLight(int vertex, int side, int material, const LightVisibility* shadows) const;

  const Scene& scene_;
  const TessellatedScene& tessellated_;
  const ScreenGeometry& screen_;
  Vec3 eye_;
  Shading shading_;
  bool anyTransparent_;
  const LightVisibility* shadows_;
  std::vector<SplitLight> faceLight_;  // flat: by screen face
  // Gouraud: by scene vertex, for each side of the surface seen (front:
  // the side its normal points to).
  std::array<std::vector<SplitLight>, 2> vertexLight_;
};

}  // namespace rise
