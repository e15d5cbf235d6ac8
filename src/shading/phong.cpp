#include "shading/phong.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

namespace rise {
namespace {

// cosine^n of a highlight, for a cosine in (0, 1]. The C library's power
// takes a slow path, which also sets errno, for every result too small for a
// float, as a sharp highlight's is over most of the surface (n = 200 and a
// cosine below 0.64). A float below 2^e (e its binary exponent plus one)
// raised to n is below 2^(e n); when that is past an eighth of the smallest
// float, the power is zero, computed or not.
float highlightPower(float cosine, float n) {
  const int exponentAbove = static_cast<int>(std::bit_cast<std::uint32_t>(cosine) >> 23) - 126;
  if (static_cast<float>(exponentAbove) * n <= -152.0f) return 0.0f;
  return std::pow(cosine, n);
}

}  // namespace

Color phongAmbient(const Material& material, const SurfaceColors& surface,
                   const Color& ambientLight) {
  return ambientLight * (material.ka * (1.0f - material.transmission)) * surface.color;
}

Color phongUnlit(const Material& material, const SurfaceColors& surface,
                 const Color& ambientLight) {
  return material.emission + phongAmbient(material, surface, ambientLight);
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
    if (cosHighlight > 0.0f) specular = surface.ks * highlightPower(cosHighlight, material.n);
  }
  return light.color * (diffuse + specular);
}

}  // namespace rise
