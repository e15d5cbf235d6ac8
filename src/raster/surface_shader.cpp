#include "raster/surface_shader.hpp"

#include "scene/textures/surface_mapping.hpp"
#include "shading/phong.hpp"

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

Color SurfaceShader::illuminate(const Material& material, const SurfaceColors& colors,
                                const Vec3& position, const Vec3& surfaceNormal,
                                const Vec3& shadingNormal) const {
  const Vec3 toViewer = glm::normalize(eye_ - position);
  Color color = phongAmbient(material, colors, scene_.ambient);
  for (const auto& light : scene_.lights) {
    const LightSample sample = light->illuminate(position);
    // A light behind the surface is hidden by it, however far a bump or
    // normal map tilts the shading normal, as the ray tracer finds.
    if (glm::dot(surfaceNormal, sample.toLight) <= 0.0f) continue;
    color += phongDirect(material, colors, shadingNormal, toViewer, sample);
  }
  return color;
}

// The model is linear in C and ks: I(C, ks) = C * I(1, 0) + ks * I(0, 1).
SurfaceShader::Illumination SurfaceShader::illumination(const Material& material,
                                                        const Vec3& position,
                                                        const Vec3& normal) const {
  return {illuminate(material, {Color(1.0f), Color(0.0f)}, position, normal, normal),
          illuminate(material, {Color(0.0f), Color(1.0f)}, position, normal, normal)};
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
          faceLight_[f] = illumination(scene_.materials[face.material], (a + b + c) / 3.0f,
                                       towardsEye(normal, sideSeen(screen_.faces[f])));
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
            vertexLight_[side][v] = illumination(scene_.materials[material[side][v]],
                                                 vertex.position, towardsEye(vertex.normal, side));
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
  const SurfaceColors colors = material.colorsOverFootprint(surface, uvFootprint(face, centre));
  const int side = sideSeen(screenFace);
  Color color;
  switch (shading_) {
    case Shading::Flat:
      color = faceLight_[face].with(colors);
      break;
    case Shading::Gouraud: {
      const std::vector<Illumination>& lit = vertexLight_[side];
      const auto& [ia, ib, ic] = sceneFace.vertices;
      const Illumination interpolated{
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
        surface.shadingNormal = material.shadingNormalAt(surface);
      }
      color = illuminate(material, colors, surface.position, towardsEye(surface.normal, side),
                         towardsEye(surface.shadingNormal, side));
      break;
  }
  return {color, glm::length(surface.position - eye_), surface.normal};
}

}  // namespace rise
