#include "radiosity/direct_light.hpp"

#include <cmath>

namespace rise {

int sideTowards(const Vec3& centre, const Vec3& normal, const Vec3& point) {
  return glm::dot(normal, point - centre) >= 0.0f ? kFrontSide : kBackSide;
}

Vec3 leaving(const Vec3& centre, const Vec3& normal, const Vec3& towards, float offset) {
  const float side = sideTowards(centre, normal, towards) == kFrontSide ? 1.0f : -1.0f;
  return centre + side * offset * normal;
}

TwoSides DirectLight::reflected(const Vec3& point, const Vec3& normal, bool twoSided,
                                const Color& reflectance, std::uint64_t& rays) const {
  return reflected(point, normal, twoSided, reflectance, &rays);
}

TwoSides DirectLight::reflectedUnblocked(const Vec3& point, const Vec3& normal, bool twoSided,
                                         const Color& reflectance) const {
  return reflected(point, normal, twoSided, reflectance, nullptr);
}

// With `rays`, the shadow rays counted there; without, none traced.
TwoSides DirectLight::reflected(const Vec3& point, const Vec3& normal, bool twoSided,
                                const Color& reflectance, std::uint64_t* rays) const {
  constexpr int kSide = 4;
  TwoSides given{Color(0.0f), Color(0.0f)};
  IntersectionCounters counters;
  for (const std::unique_ptr<Light>& light : scene_.lights)
    for (int sample = 0; sample < kSide * kSide; ++sample) {
      const Vec2 u((sample % kSide + 0.5f) / kSide, (sample / kSide + 0.5f) / kSide);
      const LightSample toLight = light->illuminate(point, u);
      const Vec3 lightPoint = point + toLight.toLight;
      const int side = sideTowards(point, normal, lightPoint);
      const float cosine = std::abs(glm::dot(normal, toLight.toLight));
      if (!(cosine > 0.0f) || (!twoSided && side == kBackSide)) continue;
      Color through(1.0f);
      if (rays != nullptr) {
        const Vec3 from = leaving(point, normal, lightPoint, offset_);
        ++*rays;
        through =
            blockers_.transmittance({from, toLight.toLight}, 0.0f, toLight.distance, counters);
      }
      given[side] +=
          reflectance * toLight.color * cosine * through / static_cast<float>(kSide * kSide);
    }
  return given;
}

}  // namespace rise
