#include "shading/scattering.hpp"

#include <algorithm>
#include <cmath>

#include "core/warps.hpp"

namespace rise {
float fresnelDielectric(float cosIncidence, float eta) {
  const float sinSquaredRefracted = (1.0f - cosIncidence * cosIncidence) / (eta * eta);
  if (sinSquaredRefracted >= 1.0f) return 1.0f;
  const float cosRefracted = std::sqrt(1.0f - sinSquaredRefracted);
  const float perpendicular =
      (cosIncidence - eta * cosRefracted) / (cosIncidence + eta * cosRefracted);
  const float parallel = (eta * cosIncidence - cosRefracted) / (eta * cosIncidence + cosRefracted);
  return 0.5f * (perpendicular * perpendicular + parallel * parallel);
}

Scattering::Scattering(const Material& material, const SurfaceColors& colors, const Vec3& normal,
                       const Vec3& toViewer, bool viewerOutside)
    : normal_(normal),
      toViewer_(toViewer),
      viewerOutside_(viewerOutside),
      ior_(material.ior),
      exponent_(material.n),
      diffuse_(material.kd * (1.0f - material.transmission) * colors.color),
      glossy_(colors.ks),
      reflection_(material.reflection),
      transmission_(material.transmission),
      tint_(colors.color) {
  const float total = maxComponent(diffuse_) + maxComponent(glossy_) + reflection_ + transmission_;
  if (total <= 0.0f) return;
  const float scale = std::min(1.0f, 1.0f / total);
  diffuse_ *= scale;
  glossy_ *= scale;
  reflection_ *= scale;
  transmission_ *= scale;
  const float scaledTotal = total * scale;
  diffuseShare_ = maxComponent(diffuse_) / scaledTotal;
  glossyShare_ = maxComponent(glossy_) / scaledTotal;
  mirrorShare_ = reflection_ / scaledTotal;
  glassShare_ = transmission_ / scaledTotal;
}

Vec3 Scattering::mirrored(const Vec3& direction) const {
  return 2.0f * glm::dot(normal_, direction) * normal_ - direction;
}

Color Scattering::brdf(const Vec3& toLight) const {
  if (glm::dot(normal_, toLight) <= 0.0f) return Color(0.0f);
  Color f = diffuse_ / kPi;
  if (glossyShare_ > 0.0f) {
    const float cosHighlight = glm::dot(mirrored(toViewer_), toLight);
    if (cosHighlight > 0.0f)
      f += glossy_ * ((exponent_ + 2.0f) / (2.0f * kPi) * std::pow(cosHighlight, exponent_));
  }
  return f;
}

float Scattering::pdf(const Vec3& toLight) const {
  const float cosine = glm::dot(normal_, toLight);
  if (cosine <= 0.0f) return 0.0f;
  float density = diffuseShare_ * cosine / kPi;
  // The lobe's density depends only on the cosine about its axis, the mirror
  // direction.
  if (glossyShare_ > 0.0f)
    density +=
        glossyShare_ *
        phongLobeDensity(Vec3(0.0f, 0.0f, glm::dot(mirrored(toViewer_), toLight)), exponent_);
  return density;
}

std::optional<ScatteringSample> Scattering::sample(const Vec2& u, float choice) const {
  ScatteringSample sample;
  if (choice < diffuseShare_ + glossyShare_) {
    // One sample of the two lobes' mixture: its weight divides by the density
    // of both, whichever chose it (Veach's one-sample model).
    const bool diffuse = choice < diffuseShare_;
    sample.direction = diffuse ? fromLocal(squareToCosineHemisphere(u), normal_)
                               : fromLocal(squareToPhongLobe(u, exponent_), mirrored(toViewer_));
    sample.pdf = pdf(sample.direction);
    if (sample.pdf <= 0.0f) return std::nullopt;
    sample.weight = brdf(sample.direction) * (glm::dot(normal_, sample.direction) / sample.pdf);
    return sample;
  }
  choice -= diffuseShare_ + glossyShare_;
  if (choice < mirrorShare_) {
    sample.direction = mirrored(toViewer_);
    sample.pdf = mirrorShare_;
    sample.weight = Color(reflection_ / mirrorShare_);
    sample.singular = true;
    return sample;
  }
  if (glassShare_ <= 0.0f) return std::nullopt;
  return sampleGlass(std::min((choice - mirrorShare_) / glassShare_, 1.0f));
}

// Reflected with Fresnel's probability, refracted otherwise: each weighed by
// the interface's share alone, as its probability is Fresnel's own.
std::optional<ScatteringSample> Scattering::sampleGlass(float choice) const {
  const float eta = viewerOutside_ ? ior_ : 1.0f / ior_;
  const float cosIncidence = glm::dot(normal_, toViewer_);
  const float reflected = fresnelDielectric(cosIncidence, eta);
  ScatteringSample sample;
  sample.singular = true;
  if (choice < reflected) {
    sample.direction = mirrored(toViewer_);
    sample.pdf = glassShare_ * reflected;
    sample.weight = Color(transmission_ / glassShare_);
    return sample;
  }
  sample.direction = glm::refract(-toViewer_, normal_, 1.0f / eta);
  sample.pdf = glassShare_ * (1.0f - reflected);
  sample.weight = transmission_ / glassShare_ * tint_;
  sample.refracted = true;
  return sample;
}

}  // namespace rise
