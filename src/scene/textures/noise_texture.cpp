#include "scene/textures/noise_texture.hpp"

#include <algorithm>
#include <cmath>

#include "scene/textures/perlin_noise.hpp"

namespace rise {

namespace {

constexpr int kTurbulenceOctaves = 6;
constexpr float kMarbleDisturbance = 6.0f;  // radians of phase per unit of turbulence
constexpr float kWoodRingsPerUnit = 4.0f;
constexpr float kWoodIrregularity = 0.25f;  // how far, in units, the noise moves a ring

}  // namespace

Color NoiseTexture::colorAt(const SurfacePoint& surface) const {
  return glm::mix(first_, second_, mixAt(surface.position));
}

float NoiseTexture::mixAt(const Vec3& position) const {
  const Vec3 point = scale_ * position;
  switch (pattern_) {
    case NoisePattern::Perlin:
      return std::clamp(0.5f + 0.5f * perlinNoise(point), 0.0f, 1.0f);
    case NoisePattern::Marble:
      return 0.5f + 0.5f * std::sin(2.0f * kPi * point.x +
                                    kMarbleDisturbance * turbulence(point, kTurbulenceOctaves));
    case NoisePattern::Wood: {
      const float radius = std::hypot(point.x, point.z) + kWoodIrregularity * perlinNoise(point);
      const float rings = kWoodRingsPerUnit * radius;
      return rings - std::floor(rings);
    }
  }
  return 0.0f;
}

}  // namespace rise
