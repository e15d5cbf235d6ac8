#include "shading/phong.hpp"

#include <cmath>

namespace rise {

Color phongAmbient(const Material& material, const SurfaceColors& surface,
                   const Color& ambientLight) {
  return ambientLight * (material.ka * (1.0f - material.transmission)) * surface.color;
}

Color phongDirect(const Material& material, const SurfaceColors& surface, const Vec3& normal,
                  const Vec3& toViewer, const LightSample& light) {
  const float cosIncidence = glm::dot(normal, light.toLight);
  if (cosIncidence <= 0.0f) return Color(0.0f);

  const Color diffuse =
      (material.kd * (1.0f - material.transmission) * cosIncidence) * surface.color;

  Color specular(0.0f);
  if (surface.ks != Color(0.0f)) {
    const Vec3 mirroredLight = glm::reflect(-light.toLight, normal);
    const float cosHighlight = glm::dot(mirroredLight, toViewer);
    if (cosHighlight > 0.0f) specular = surface.ks * std::pow(cosHighlight, material.n);
  }
  return light.color * (diffuse + specular);
}

}  // namespace rise
