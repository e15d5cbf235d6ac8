#include "shading/local_illumination.hpp"

#include "shading/phong.hpp"

namespace rise {

Color unshadowedLight(const Scene& scene, const Material& material, const SurfaceColors& colors,
                      const Vec3& position, const Vec3& surfaceNormal, const Vec3& shadingNormal,
                      const Vec3& eye) {
  const Vec3 toViewer = glm::normalize(eye - position);
  Color color = phongAmbient(material, colors, scene.ambient);
  for (const auto& light : scene.lights) {
    const LightSample sample = light->illuminate(position);
    if (glm::dot(surfaceNormal, sample.toLight) <= 0.0f) continue;
    color += phongDirect(material, colors, shadingNormal, toViewer, sample);
  }
  return color;
}

SplitLight splitUnshadowedLight(const Scene& scene, const Material& material, const Vec3& position,
                                const Vec3& normal, const Vec3& eye) {
  return {
      unshadowedLight(scene, material, {Color(1.0f), Color(0.0f)}, position, normal, normal, eye),
      unshadowedLight(scene, material, {Color(0.0f), Color(1.0f)}, position, normal, normal, eye)};
}

}  // namespace rise
