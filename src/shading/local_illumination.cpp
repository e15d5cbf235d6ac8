#include "shading/local_illumination.hpp"

#include "shading/phong.hpp"

namespace rise {
namespace {

// Calls lit(sample, reaching) for each light in front of the surface that
// some of its light reaches, asking `shadows` once per light.
template <typename Lit>
void forEachLightReaching(const Scene& scene, const Vec3& position, const Vec3& surfaceNormal,
                          const LightVisibility* shadows, const Lit& lit) {
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    const LightSample sample = scene.lights[light]->illuminate(position);
    if (glm::dot(surfaceNormal, sample.toLight) <= 0.0f) continue;
    const Color reaching =
        shadows ? shadows->reaching(static_cast<int>(light), position, surfaceNormal) : Color(1.0f);
    if (reaching != Color(0.0f)) lit(sample, reaching);
  }
}

}  // namespace

Color localLight(const Scene& scene, const Material& material, const SurfaceColors& colors,
                 const Vec3& position, const Vec3& surfaceNormal, const Vec3& shadingNormal,
                 const Vec3& eye, const LightVisibility* shadows) {
  const Vec3 toViewer = glm::normalize(eye - position);
  Color color = phongUnlit(material, colors, scene.ambient);
  forEachLightReaching(scene, position, surfaceNormal, shadows,
                       [&](const LightSample& sample, const Color& reaching) {
                         color += reaching *
                                  phongDirect(material, colors, shadingNormal, toViewer, sample);
                       });
  return color;
}

SplitLight splitLocalLight(const Scene& scene, const Material& material, const Vec3& position,
                           const Vec3& normal, const Vec3& eye, const LightVisibility* shadows) {
  const Vec3 toViewer = glm::normalize(eye - position);
  const SurfaceColors byColor{Color(1.0f), Color(0.0f)}, byKs{Color(0.0f), Color(1.0f)};
  SplitLight split{phongAmbient(material, byColor, scene.ambient),
                   phongAmbient(material, byKs, scene.ambient), material.emission};
  forEachLightReaching(
      scene, position, normal, shadows, [&](const LightSample& sample, const Color& reaching) {
        split.byColor += reaching * phongDirect(material, byColor, normal, toViewer, sample);
        split.byKs += reaching * phongDirect(material, byKs, normal, toViewer, sample);
      });
  return split;
}

}  // namespace rise
