// The accumulation buffer's camera effects (Haeberli and Akeley 1990) against
// the distributed ray tracer's (Cook et al. 1984): images of the depth of
// field and motion blur examples, passes spread over the lens and the shutter
// interval, must match the ray tracer's rays spread over them. Lights are
// taken out, ambient light alone left, since the visible-surface algorithms
// draw no shadows.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_file.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

Scene ambientExample(const std::string& name) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  scene.image.width = 96;
  scene.image.height = 54;
  scene.lights.clear();
  scene.ambient = Color(1.0f);
  return scene;
}

RenderSettings accumulating(const Scene& scene) {
  RenderSettings settings = settingsFor(scene);
  settings.sampling.samples = 64;
  settings.sampling.pattern = SamplePattern::Jittered;
  return settings;
}

float meanDifference(const Image& a, const Image& b) {
  float sum = 0.0f;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) sum += maxComponent(glm::abs(a.at(x, y) - b.at(x, y)));
  return sum / static_cast<float>(a.width() * a.height());
}

void expectTheRayTracersEffect(const Scene& scene, const Scene& withoutEffect) {
  const RenderSettings settings = accumulating(scene);
  const Image rays = render("distributed-ray-tracing", scene, settings).image;
  const Image sharp = render("z-buffer", withoutEffect, settings).image;
  // The effect changes a small part of the image (the rest is sky and floor
  // that neither focus nor motion touches), so the measure is relative: the
  // accumulated image must lie much nearer the rays' than the sharp one does,
  // as near as the two estimates' noise and their texture filters allow.
  const float effect = meanDifference(sharp, rays);
  EXPECT_GT(effect, 0.005f);
  for (std::string_view algorithm : kAlgorithms) {
    const Image image = render(algorithm, scene, settings).image;
    EXPECT_LT(meanDifference(image, rays), 0.4f * effect) << algorithm;
  }
}

TEST(AccumulationBuffer, BlursOutOfFocusAsTheThinLensRaysDo) {
  const Scene scene = ambientExample("depth-of-field.yaml");
  ASSERT_GT(scene.camera.aperture, 0.0f);
  Scene pinhole = ambientExample("depth-of-field.yaml");
  pinhole.camera.aperture = 0.0f;
  expectTheRayTracersEffect(scene, pinhole);
}

TEST(AccumulationBuffer, BlursMotionAsRaysSpreadOverTheShutterDo) {
  const Scene scene = ambientExample("motion-blur.yaml");
  ASSERT_TRUE(scene.camera.hasMotionBlur());
  Scene still = ambientExample("motion-blur.yaml");
  still.camera.shutterClose = still.camera.shutterOpen;
  expectTheRayTracersEffect(scene, still);
}

}  // namespace
}  // namespace rise
