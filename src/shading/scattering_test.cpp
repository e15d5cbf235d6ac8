#include "shading/scattering.hpp"

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "support/chi_square_testing.hpp"

namespace rise {
namespace {

using namespace chi_square_testing;

// The chi-square tests of this file, each held to its share of 0.01.
constexpr int kTests = 3;
const double kSignificance = significanceFor(kTests);

Material phongMaterial(float kd, float ks, float n) {
  Material material;
  material.kd = kd;
  material.ks = ks;
  material.n = n;
  return material;
}

Scattering scatteringOf(const Material& material, const Vec3& toViewer) {
  return Scattering(material, {material.color, Color(material.ks)}, Vec3(0.0f, 0.0f, 1.0f),
                    glm::normalize(toViewer), true);
}

// Its samples follow the density it claims for them, as pbrt-v4, Mitsuba 3
// and Nori test their BSDFs: Lambert's lobe alone seen obliquely, and
// Lambert's with a highlight's, whose choice between them is a third random
// number.
TEST(Scattering, SamplesFollowTheDensityItGives) {
  const struct {
    Material material;
    Vec3 toViewer;
  } cases[] = {{phongMaterial(0.8f, 0.0f, 1.0f), Vec3(1.0f, 0.0f, 1.0f)},
               {phongMaterial(0.5f, 0.4f, 20.0f), Vec3(0.0f, 0.0f, 1.0f)},
               {phongMaterial(0.1f, 0.8f, 200.0f), Vec3(0.0f, 0.0f, 1.0f)}};
  for (const auto& [material, toViewer] : cases) {
    const Scattering scattering = scatteringOf(material, toViewer);
    Rng choices(7);
    const ChiSquareOutcome outcome = chiSquareOfDirections(
        [&](const Vec2& u) {
          const std::optional<ScatteringSample> sample = scattering.sample(u, choices.uniform());
          return sample ? sample->direction : Vec3(0.0f);
        },
        [&](const Vec3& direction) { return scattering.pdf(direction); });
    EXPECT_TRUE(outcome.passes(kSignificance))
        << "kd " << material.kd << " ks " << material.ks << ": " << outcome.report;
  }
}

// The light it returns is never more than the light it receives, from any
// direction, even for coefficients whose sum passes 1: the mean of
// f cos / pdf over its samples is its albedo.
TEST(Scattering, ReturnsNoMoreLightThanItReceives) {
  const Material materials[] = {phongMaterial(0.9f, 0.9f, 5.0f), phongMaterial(1.0f, 0.0f, 1.0f),
                                phongMaterial(0.0f, 1.0f, 1.0f), phongMaterial(0.0f, 1.0f, 400.0f)};
  Rng rng(3);
  for (const Material& material : materials)
    for (int i = 0; i < 10; ++i) {
      const float angle = 0.15f * static_cast<float>(i);
      const Scattering scattering =
          scatteringOf(material, Vec3(std::sin(angle), 0.0f, std::cos(angle)));
      double albedo = 0.0;
      constexpr int kSamples = 16384;
      for (int s = 0; s < kSamples; ++s) {
        const float u = rng.uniform(), v = rng.uniform();
        if (const auto sample = scattering.sample({u, v}, rng.uniform()))
          albedo += sample->weight.g;
      }
      EXPECT_LT(albedo / kSamples, 1.01) << "kd " << material.kd << " ks " << material.ks << " n "
                                         << material.n << " at " << angle;
    }
}

// A matte surface of albedo kd returns kd of the light at every angle.
TEST(Scattering, LambertsSurfaceReturnsItsAlbedo) {
  const Scattering scattering =
      scatteringOf(phongMaterial(0.6f, 0.0f, 1.0f), Vec3(0.3f, 0.0f, 1.0f));
  Rng rng(11);
  double albedo = 0.0;
  for (int s = 0; s < 4096; ++s) {
    const float u = rng.uniform(), v = rng.uniform();
    albedo += scattering.sample({u, v}, rng.uniform())->weight.r;
  }
  EXPECT_NEAR(albedo / 4096, 0.6, 1e-4);
}

TEST(Scattering, GlassReflectsFresnelsShareAndPassesTheRest) {
  EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-4f);
  EXPECT_FLOAT_EQ(fresnelDielectric(0.1f, 1.0f / 1.5f), 1.0f);  // past the critical angle
  Material glass;
  glass.kd = 0.0f;
  glass.transmission = 1.0f;
  glass.ior = 1.5f;
  const Scattering scattering = scatteringOf(glass, Vec3(0.0f, 0.0f, 1.0f));
  int reflected = 0;
  constexpr int kSamples = 20000;
  Rng rng(5);
  for (int s = 0; s < kSamples; ++s) {
    const std::optional<ScatteringSample> sample = scattering.sample({0.5f, 0.5f}, rng.uniform());
    ASSERT_TRUE(sample && sample->singular);
    EXPECT_FLOAT_EQ(sample->weight.r, 1.0f);
    reflected += !sample->refracted;
  }
  EXPECT_NEAR(static_cast<double>(reflected) / kSamples, 0.04, 0.005);
}

}  // namespace
}  // namespace rise
