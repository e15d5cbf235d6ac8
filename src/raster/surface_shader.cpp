#include "raster/surface_shader.hpp"

#include <algorithm>

#include "scene/shapes/vertex_attributes.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {
namespace {

constexpr int kItemsPerRange = 4096;
constexpr int kFront = 0;
constexpr int kBack = 1;

int sideSeen(const ScreenFace& face) { return face.frontFacing ? kFront : kBack; }

// The unit normal of the plane of a face's corners, around which they wind
// counter-clockwise.
Vec3 planeNormal(const SurfaceVertex& a, const SurfaceVertex& b, const SurfaceVertex& c) {
  return glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
}

// Gouraud's weights of a face's corners: their barycentric coordinates
// times the lengths of their normals (SurfaceVertex::normal), summing to 1.
Vec3 gouraudWeights(const Vec3& weights, const std::array<const SurfaceVertex*, 3>& corners) {
  Vec3 weighed = weights;
  for (int corner = 0; corner < 3; ++corner)
    weighed[corner] *= glm::length(corners[corner]->normal);
  const float sum = weighed.x + weighed.y + weighed.z;
  return sum > 0.0f ? weighed / sum : weights;
}

// A normal of the surface turned to the side the eye sees.
Vec3 towardsEye(const Vec3& normal, int side) { return side == kFront ? normal : -normal; }

}  // namespace

SurfaceShader::SurfaceShader(const Scene& scene, const TessellatedScene& tessellated,
                             const ScreenGeometry& screen, const ViewProjection& view,
                             Shading shading, const Workers& workers,
                             const LightVisibility* shadows)
    : scene_(scene),
      tessellated_(tessellated),
      screen_(screen),
      eye_(view.eye()),
      shading_(shading),
      anyTransparent_(
          std::any_of(scene.materials.begin(), scene.materials.end(),
                      [](const Material& material) { return material.isTransparent(); })),
      shadows_(shadows) {
  if (!tessellated_.vertexRadiance[kFront].empty()) return;
  if (shading_ == Shading::Flat) lightFaces(workers);
  if (shading_ == Shading::Gouraud) lightVertices(workers);
}

void SurfaceShader::lightFaces(const Workers& workers) {
  faceLight_.resize(screen_.faces.size());
  workers.forEachRange(static_cast<int>(faceLight_.size()), kItemsPerRange,
                       [&](int, int begin, int end) {
                         for (int f = begin; f < end; ++f) faceLight_[f] = faceLight(f, shadows_);
                       });
}

SplitLight SurfaceShader::faceLight(int f, const LightVisibility* shadows) const {
  const SceneFace& face = tessellated_.faces[screen_.faces[f].sceneFace];
  const SurfaceVertex& a = tessellated_.vertices[face.vertices[0]];
  const SurfaceVertex& b = tessellated_.vertices[face.vertices[1]];
  const SurfaceVertex& c = tessellated_.vertices[face.vertices[2]];
  return splitLocalLight(
      scene_, scene_.materials[face.material], (a.position + b.position + c.position) / 3.0f,
      towardsEye(planeNormal(a, b, c), sideSeen(screen_.faces[f])), eye_, shadows);
}

SplitLight SurfaceShader::vertexLight(int v, int side, int material,
                                      const LightVisibility* shadows) const {
  const SurfaceVertex& vertex = tessellated_.vertices[v];
  return splitLocalLight(scene_, scene_.materials[material], vertex.position,
                         towardsEye(normalizedOrZero(vertex.normal), side), eye_, shadows);
}

void SurfaceShader::lightVertices(const Workers& workers) {
  // Only the vertices of faces in view, on the sides seen, as a graphics
  // pipeline lights only the vertices it is given.
  const std::size_t vertexCount = tessellated_.vertices.size();
  std::array<std::vector<int>, 2> material;
  for (const ScreenFace& screenFace : screen_.faces) {
    const SceneFace& face = tessellated_.faces[screenFace.sceneFace];
    std::vector<int>& sideMaterial = material[sideSeen(screenFace)];
    if (sideMaterial.empty()) sideMaterial.assign(vertexCount, -1);
    for (int vertex : face.vertices) sideMaterial[vertex] = face.material;
  }
  for (int side : {kFront, kBack}) {
    if (material[side].empty()) continue;
    vertexLight_[side].resize(vertexCount);
    workers.forEachRange(
        static_cast<int>(vertexCount), kItemsPerRange, [&](int, int begin, int end) {
          for (int v = begin; v < end; ++v) {
            if (material[side][v] >= 0)
              vertexLight_[side][v] = vertexLight(v, side, material[side][v], shadows_);
          }
        });
  }
}

// How far the texture coordinates move from this pixel to the next across
// and down, by the face's perspective-correct barycentric coordinates one
// pixel away: the corners' coordinates interpolated there, or the shape's
// projection at the points there.
PixelFootprint SurfaceShader::uvFootprint(int face, const Vec2& centre,
                                          const SurfacePoint& surface) const {
  const ScreenFace& screenFace = screen_.faces[face];
  const SceneFace& sceneFace = tessellated_.faces[screenFace.sceneFace];
  const std::optional<PlacedProjection>& projection = tessellated_.projections[sceneFace.shape];
  const auto stepTo = [&](const Vec2& raster) {
    const Vec3 weights = screenFace.barycentricAt(raster);
    const auto at = [&](auto member) {
      return weights.x * tessellated_.vertices[sceneFace.vertices[0]].*member +
             weights.y * tessellated_.vertices[sceneFace.vertices[1]].*member +
             weights.z * tessellated_.vertices[sceneFace.vertices[2]].*member;
    };
    return projection ? projection->stepTo(surface, at(&SurfaceVertex::position))
                      : at(&SurfaceVertex::uv) - surface.uv;
  };
  return {stepTo(centre + Vec2(1.0f, 0.0f)), stepTo(centre + Vec2(0.0f, 1.0f))};
}

SurfacePoint SurfaceShader::surfaceAt(int face, const Vec3& weights) const {
  const SceneFace& sceneFace = tessellated_.faces[screen_.faces[face].sceneFace];
  const SurfaceVertex& a = tessellated_.vertices[sceneFace.vertices[0]];
  const SurfaceVertex& b = tessellated_.vertices[sceneFace.vertices[1]];
  const SurfaceVertex& c = tessellated_.vertices[sceneFace.vertices[2]];
  SurfacePoint surface(weights.x * a.position + weights.y * b.position + weights.z * c.position,
                       interpolatedNormal(planeNormal(a, b, c), a.normal, b.normal, c.normal,
                                          Vec2(weights.y, weights.z)),
                       weights.x * a.uv + weights.y * b.uv + weights.z * c.uv);
  const std::optional<PlacedProjection>& projection = tessellated_.projections[sceneFace.shape];
  if (projection) projection->mapOnto(surface);
  return surface;
}

ShadedPixel SurfaceShader::shade(int face, const Vec2& centre, const LightVisibility* pixelShadows,
                                 PixelGeometry geometry) const {
  const ScreenFace& screenFace = screen_.faces[face];
  const SceneFace& sceneFace = tessellated_.faces[screenFace.sceneFace];
  const Vec3 weights = screenFace.barycentricAt(centre);
  const SurfaceVertex& a = tessellated_.vertices[sceneFace.vertices[0]];
  const SurfaceVertex& b = tessellated_.vertices[sceneFace.vertices[1]];
  const SurfaceVertex& c = tessellated_.vertices[sceneFace.vertices[2]];
  if (!tessellated_.vertexRadiance[kFront].empty()) {
    const std::vector<Color>& solved = tessellated_.vertexRadiance[sideSeen(screenFace)];
    const Color color = weights.x * solved[sceneFace.vertices[0]] +
                        weights.y * solved[sceneFace.vertices[1]] +
                        weights.z * solved[sceneFace.vertices[2]];
    if (geometry == PixelGeometry::Skipped) return {color, 0.0f, Vec3(0.0f)};
    const SurfacePoint surface = surfaceAt(face, weights);
    return {color, glm::length(surface.position - eye_), surface.normal};
  }
  const Material& material = scene_.materials[sceneFace.material];
  const bool textured = material.texture || material.ksTexture;
  // Flat and Gouraud shading of an untextured material need no point of
  // the surface, only its face or its corners' light.
  const bool readsSurface =
      geometry == PixelGeometry::Wanted || shading_ == Shading::Phong || textured;
  SurfacePoint surface = readsSurface ? surfaceAt(face, weights) : SurfacePoint();

  // The footprint is found only where a texture is there to be averaged over it.
  const SurfaceColors colors =
      textured ? surfaceColors(material, surface, uvFootprint(face, centre, surface))
               : surfaceColors(material, surface);
  const int side = sideSeen(screenFace);
  Color color;
  switch (shading_) {
    case Shading::Flat:
      color = (pixelShadows ? faceLight(face, pixelShadows) : faceLight_[face]).with(colors);
      break;
    case Shading::Gouraud: {
      std::array<SplitLight, 3> lit;
      for (int corner = 0; corner < 3; ++corner) {
        const int vertex = sceneFace.vertices[corner];
        lit[corner] = pixelShadows ? vertexLight(vertex, side, sceneFace.material, pixelShadows)
                                   : vertexLight_[side][vertex];
      }
      const Vec3 w = gouraudWeights(weights, {&a, &b, &c});
      const SplitLight interpolated{
          w.x * lit[0].byColor + w.y * lit[1].byColor + w.z * lit[2].byColor,
          w.x * lit[0].byKs + w.y * lit[1].byKs + w.z * lit[2].byKs, lit[0].emitted};
      color = interpolated.with(colors);
      break;
    }
    case Shading::Phong:
      // Bump and normal maps tilt the normal at every pixel, Phong shading
      // alone having a normal per pixel.
      if (material.bump || material.normalMap) {
        if (!tessellated_.projections[sceneFace.shape])
          triangleTangents(a.position, b.position, c.position, a.uv, b.uv, c.uv, surface.dpdu,
                           surface.dpdv);
        surface.shadingNormal = shadingNormal(material, surface);
      }
      color = localLight(scene_, material, colors, surface.position,
                         towardsEye(surface.normal, side), towardsEye(surface.shadingNormal, side),
                         eye_, pixelShadows ? pixelShadows : shadows_);
      break;
  }
  if (geometry == PixelGeometry::Skipped) return {color, 0.0f, Vec3(0.0f)};
  return {color, glm::length(surface.position - eye_), surface.normal};
}

}  // namespace rise
