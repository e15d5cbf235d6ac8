#include "raster/surface_shader.hpp"

#include "scene/textures/surface_mapping.hpp"

namespace rise {
namespace {

constexpr int kItemsPerRange = 4096;
constexpr int kFront = 0;
constexpr int kBack = 1;

int sideSeen(const ScreenFace& face) { return face.frontFacing ? kFront : kBack; }

// A normal of the surface turned to the side the eye sees.
Vec3 towardsEye(const Vec3& normal, int side) { return side == kFront ? normal : -normal; }

}  // namespace

SurfaceShader::SurfaceShader(const Scene& scene, const TessellatedScene& tessellated,
                             const ScreenGeometry& screen, const ViewProjection& view,
                             Shading shading, const Workers& workers)
    : scene_(scene),
      tessellated_(tessellated),
      screen_(screen),
      eye_(view.eye()),
      shading_(shading) {
  if (shading_ == Shading::Flat) lightFaces(workers);
  if (shading_ == Shading::Gouraud) lightVertices(workers);
}

void SurfaceShader::lightFaces(const Workers& workers) {
  faceLight_.resize(screen_.faces.size());
  workers.forEachRange(
      static_cast<int>(faceLight_.size()), kItemsPerRange, [&](int, int begin, int end) {
        for (int f = begin; f < end; ++f) {
          const SceneFace& face = tessellated_.faces[screen_.faces[f].sceneFace];
          const Vec3& a = tessellated_.vertices[face.vertices[0]].position;
          const Vec3& b = tessellated_.vertices[face.vertices[1]].position;
          const Vec3& c = tessellated_.vertices[face.vertices[2]].position;
          const Vec3 normal = glm::normalize(glm::cross(b - a, c - a));
          faceLight_[f] =
              splitUnshadowedLight(scene_, scene_.materials[face.material], (a + b + c) / 3.0f,
                                   towardsEye(normal, sideSeen(screen_.faces[f])), eye_);
        }
      });
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
            if (material[side][v] < 0) continue;
            const SurfaceVertex& vertex = tessellated_.vertices[v];
            vertexLight_[side][v] =
                splitUnshadowedLight(scene_, scene_.materials[material[side][v]], vertex.position,
                                     towardsEye(vertex.normal, side), eye_);
          }
        });
  }
}

// How far the texture coordinates move from this pixel to the next across
// and down, by the face's perspective-correct barycentric coordinates one
// pixel away.
PixelFootprint SurfaceShader::uvFootprint(int face, const Vec2& centre) const {
  const ScreenFace& screenFace = screen_.faces[face];
  const SceneFace& sceneFace = tessellated_.faces[screenFace.sceneFace];
  const auto uvAt = [&](const Vec2& raster) {
    const Vec3 weights = screenFace.barycentricAt(raster);
    return weights.x * tessellated_.vertices[sceneFace.vertices[0]].uv +
           weights.y * tessellated_.vertices[sceneFace.vertices[1]].uv +
           weights.z * tessellated_.vertices[sceneFace.vertices[2]].uv;
  };
  const Vec2 here = uvAt(centre);
  return {uvAt(centre + Vec2(1.0f, 0.0f)) - here, uvAt(centre + Vec2(0.0f, 1.0f)) - here};
}

ShadedPixel SurfaceShader::shade(int face, const Vec2& centre) const {
  const ScreenFace& screenFace = screen_.faces[face];
  const SceneFace& sceneFace = tessellated_.faces[screenFace.sceneFace];
  const Vec3 weights = screenFace.barycentricAt(centre);
  const SurfaceVertex& a = tessellated_.vertices[sceneFace.vertices[0]];
  const SurfaceVertex& b = tessellated_.vertices[sceneFace.vertices[1]];
  const SurfaceVertex& c = tessellated_.vertices[sceneFace.vertices[2]];
  SurfacePoint surface(
      weights.x * a.position + weights.y * b.position + weights.z * c.position,
      glm::normalize(weights.x * a.normal + weights.y * b.normal + weights.z * c.normal),
      weights.x * a.uv + weights.y * b.uv + weights.z * c.uv);

  const Material& material = scene_.materials[sceneFace.material];
  const SurfaceColors colors = surfaceColors(material, surface, uvFootprint(face, centre));
  const int side = sideSeen(screenFace);
  Color color;
  switch (shading_) {
    case Shading::Flat:
      color = faceLight_[face].with(colors);
      break;
    case Shading::Gouraud: {
      const std::vector<SplitLight>& lit = vertexLight_[side];
      const auto& [ia, ib, ic] = sceneFace.vertices;
      const SplitLight interpolated{
          weights.x * lit[ia].byColor + weights.y * lit[ib].byColor + weights.z * lit[ic].byColor,
          weights.x * lit[ia].byKs + weights.y * lit[ib].byKs + weights.z * lit[ic].byKs};
      color = interpolated.with(colors);
      break;
    }
    case Shading::Phong:
      // Bump and normal maps tilt the normal at every pixel, Phong shading
      // alone having a normal per pixel.
      if (material.bump || material.normalMap) {
        triangleTangents(a.position, b.position, c.position, a.uv, b.uv, c.uv, surface.dpdu,
                         surface.dpdv);
        surface.shadingNormal = shadingNormal(material, surface);
      }
      color = unshadowedLight(scene_, material, colors, surface.position,
                              towardsEye(surface.normal, side),
                              towardsEye(surface.shadingNormal, side), eye_);
      break;
  }
  return {color, glm::length(surface.position - eye_), surface.normal};
}

}  // namespace rise
