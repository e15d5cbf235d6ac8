// The hybrid algorithm's camera effects: each accumulation pass, seen from
// its point of the lens at its instant of the shutter interval, must be the
// image that Whitted's recursion gives along the thin-lens rays from that
// point at that instant (the distributed ray tracer's rays, with one lens
// point and one instant for the whole image); and many passes must blur as
// the distributed ray tracer does.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_file.hpp"
#include "ray/distributed_ray_tracing.hpp"
#include "ray/ray_tracing.hpp"
#include "support/hybrid_testing.hpp"

namespace rise {
namespace {

using namespace hybrid_testing;
using raster_testing::render;

Scene example(const std::string& name) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  scene.image.width = 96;
  scene.image.height = 54;
  return scene;
}

// Whitted's recursion along the rays of one accumulation pass.
Image tracedAlongThePass(const Scene& scene, const RenderSettings& settings,
                         const AccumulationPass& pass) {
  const SceneIntersector intersector(scene, settings.accel, 1);
  const ViewFrame view(scene.camera, settings.width, settings.height);
  const TracingContext context{scene, intersector, settings.maxDepth, view};
  Image image(settings.width, settings.height);
  TraceCounters counters;
  SingleRayChoices whitted;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      Ray ray = thinLensRay(
          view, Vec2(static_cast<float>(x), static_cast<float>(y)) + pass.pixelOffset, pass.lens);
      ray.time = pass.time;
      image.at(x, y) = tracePrimary(context, ray, whitted, counters).color;
    }
  }
  return image;
}

// One sample a pixel: one pass, from a point of the lens and an instant the
// render's seed picks.
void expectThePassesRays(const Scene& scene) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    RenderSettings settings = settingsFor(scene);
    settings.sampling = PixelSampling{1, SamplePattern::Jittered, FilterKind::Box};
    settings.seed = seed;
    const std::vector<AccumulationPass> passes = accumulationPasses(scene.camera, settings);
    ASSERT_EQ(passes.size(), 1u);
    const RenderResult hybrid = render("hybrid", scene, settings);
    const Agreement agreement =
        compareImages(scene, settings, hybrid, tracedAlongThePass(scene, settings, passes[0]));
    EXPECT_LE(agreement.differing, 4) << "seed " << seed;
    EXPECT_EQ(agreement.differingInside, 0) << "seed " << seed;
  }
}

TEST(HybridEffects, EachPassSeesThroughItsPointOfTheLens) {
  const Scene scene = example("depth-of-field.yaml");
  ASSERT_GT(scene.camera.aperture, 0.0f);
  expectThePassesRays(scene);
}

TEST(HybridEffects, EachPassSeesTheSceneAtItsInstant) {
  const Scene scene = example("motion-blur.yaml");
  ASSERT_TRUE(scene.camera.hasMotionBlur());
  expectThePassesRays(scene);
}

float meanDifference(const Image& a, const Image& b) {
  float sum = 0.0f;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) sum += maxComponent(glm::abs(a.at(x, y) - b.at(x, y)));
  return sum / static_cast<float>(a.width() * a.height());
}

// Many passes: the blur converges on the distributed ray tracer's, which
// spreads its samples over the lens and the shutter pixel by pixel.
TEST(HybridEffects, BlursAsTheDistributedRayTracerDoes) {
  for (const char* name : {"depth-of-field.yaml", "motion-blur.yaml"}) {
    const Scene scene = example(name);
    Scene sharp = example(name);
    sharp.camera.aperture = 0.0f;
    sharp.camera.shutterClose = sharp.camera.shutterOpen;
    RenderSettings settings = settingsFor(scene);
    settings.sampling = PixelSampling{64, SamplePattern::Jittered, FilterKind::Box};
    const Image rays = render("distributed-ray-tracing", scene, settings).image;
    const float effect = meanDifference(render("ray-tracing", sharp, settings).image, rays);
    EXPECT_GT(effect, 0.005f) << name;
    EXPECT_LT(meanDifference(render("hybrid", scene, settings).image, rays), 0.4f * effect) << name;
  }
}

}  // namespace
}  // namespace rise
