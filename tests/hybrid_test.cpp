// The hybrid scan-line / ray-tracing algorithm against Whitted's ray tracer,
// whose image it renders by other means: on every example scene and on
// random scenes of spheres, boxes and meshes with mirrors and glass, the two
// images agree but for a few pixels on outlines, none inside an object; and
// its item buffer is the scanline algorithm's face buffer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/scene_file.hpp"
#include "support/example_testing.hpp"
#include "support/hybrid_testing.hpp"

namespace rise {
namespace {

using namespace example_testing;
using namespace hybrid_testing;
using raster_testing::render;

// Silhouette pixels the rule misses: a sliver of a curved object's outline
// where none of its polygons is seen beside it.
constexpr int kAllowedDiffering = 4;

// The example as Whitted's ray tracer sees it: through a pinhole, at the
// shutter's opening.
Scene pinholeExample(const std::string& name, int width, int height) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  scene.image.width = width;
  scene.image.height = height;
  scene.camera.aperture = 0.0f;
  scene.camera.shutterClose = scene.camera.shutterOpen;
  return scene;
}

RenderSettings oneSampleAPixel(const Scene& scene) {
  RenderRequest request;
  request.image = {scene.image.width,   scene.image.height, 1,
                   SamplePattern::None, FilterKind::Box,    {}};
  return settingsFor(scene, request);
}

void expectWhittedsImage(const Scene& scene, const RenderSettings& settings) {
  const RenderResult hybrid = render("hybrid", scene, settings);
  const RenderResult whitted = render("ray-tracing", scene, settings);
  const Agreement agreement = compareImages(scene, settings, hybrid, whitted.image);
  EXPECT_LE(agreement.differing, kAllowedDiffering);
  EXPECT_EQ(agreement.differingInside, 0);
}

void expectTheScanlinesFaceBuffer(const Scene& scene, const RenderSettings& settings) {
  const RenderResult hybrid = render("hybrid", scene, settings);
  const RenderResult scanline = render("scanline", scene, settings);
  EXPECT_EQ(raster_testing::pixelsSeeingOtherFaces(hybrid, scanline), 0);
}

class HybridOnExample : public testing::TestWithParam<std::string> {};

TEST_P(HybridOnExample, RendersWhittedsImage) {
  for (const auto& [width, height] : {std::pair{64, 48}, std::pair{45, 80}}) {
    const Scene scene = pinholeExample(GetParam(), width, height);
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    expectWhittedsImage(scene, oneSampleAPixel(scene));
  }
}

TEST_P(HybridOnExample, ItsItemBufferIsTheScanlinesFaceBuffer) {
  const Scene scene = pinholeExample(GetParam(), 64, 48);
  expectTheScanlinesFaceBuffer(scene, oneSampleAPixel(scene));
}

INSTANTIATE_TEST_SUITE_P(Examples, HybridOnExample, testing::ValuesIn(exampleScenes()),
                         exampleTestName);

class HybridOnRandomScene : public testing::TestWithParam<int> {
 protected:
  // Sizes and aspect ratios other than the examples' own, seed by seed.
  static Scene scene() {
    const int seed = GetParam();
    const int sizes[][2] = {{96, 72}, {60, 100}, {128, 48}};
    const auto& [width, height] = sizes[seed % 3];
    return randomScene(static_cast<std::uint64_t>(seed), width, height);
  }
};

TEST_P(HybridOnRandomScene, RendersWhittedsImage) {
  const Scene random = scene();
  expectWhittedsImage(random, oneSampleAPixel(random));
}

TEST_P(HybridOnRandomScene, ItsItemBufferIsTheScanlinesFaceBuffer) {
  const Scene random = scene();
  expectTheScanlinesFaceBuffer(random, oneSampleAPixel(random));
}

// The face buffers are the first pass's: with jittered samples, one whose
// projection is moved in the pixel.
TEST_P(HybridOnRandomScene, ItsItemBufferIsTheScanlinesFaceBufferAtAnyOffset) {
  const Scene random = scene();
  RenderSettings settings = oneSampleAPixel(random);
  settings.sampling.samples = 3;
  settings.sampling.pattern = SamplePattern::Jittered;
  settings.seed = static_cast<std::uint64_t>(GetParam());
  expectTheScanlinesFaceBuffer(random, settings);
}

INSTANTIATE_TEST_SUITE_P(Seeds, HybridOnRandomScene, testing::Range(1, 13));

// Several samples a pixel on the same regular grid in every pixel: the
// accumulation passes take the samples Whitted's tracer takes.
TEST(Hybrid, AntiAliasesAsWhittedDoesWithTheSameSamples) {
  const Scene scene = randomScene(99, 80, 60);
  RenderSettings settings = oneSampleAPixel(scene);
  settings.sampling.samples = 4;
  settings.sampling.pattern = SamplePattern::Regular;
  expectWhittedsImage(scene, settings);
}

// With a circle cut into four segments, a sphere's polygons lie far inside
// its true outline, and the item buffer is wrong on a band of pixels around
// it: the outline is followed outwards pixel by pixel, past the pixels of
// the band already shaded from the item buffer, which are shaded again.
TEST(Hybrid, FollowsAnOutlineFarBeyondCoarsePolygons) {
  const Scene scene = pinholeExample("classic.yaml", 96, 72);
  RenderSettings settings = oneSampleAPixel(scene);
  settings.tessellation = 1;
  expectWhittedsImage(scene, settings);
  const Stats stats = render("hybrid", scene, settings).stats;
  EXPECT_EQ(stats.value("primary_rays") + stats.value("primary_rays_from_item_buffer"), 96 * 72);
  EXPECT_EQ(stats.value("fallback_pixels"), stats.value("primary_rays"));
  EXPECT_GT(stats.value("fallback_pixels_inside_outline"), 200.0);
}

// With several samples a pixel, the outline's pixels already shaded from the
// item buffer have their first samples taken back from the image that all
// the samples of a group of passes share, and the full primary rays' put in.
TEST(Hybrid, FollowsAnOutlineBeyondCoarsePolygonsInEverySample) {
  const Scene scene = pinholeExample("classic.yaml", 80, 60);
  RenderSettings settings = oneSampleAPixel(scene);
  settings.tessellation = 1;
  settings.sampling.samples = 9;
  settings.sampling.pattern = SamplePattern::Regular;
  expectWhittedsImage(scene, settings);
  EXPECT_GT(render("hybrid", scene, settings).stats.value("fallback_pixels_inside_outline"),
            9 * 150.0);
}

// The counters explain the work: every sample is answered by the item
// buffer or by a full primary ray, the full ones are the fallback pixels, and
// a scene without mirrors or glass spawns shadow rays only.
TEST(Hybrid, CountsWhereItsPrimaryRaysCameFrom) {
  Scene scene = pinholeExample("classic.yaml", 80, 60);
  RenderSettings settings = oneSampleAPixel(scene);
  settings.sampling.samples = 2;
  settings.sampling.pattern = SamplePattern::Jittered;
  const Stats stats = render("hybrid", scene, settings).stats;
  EXPECT_EQ(stats.value("primary_rays") + stats.value("primary_rays_from_item_buffer"),
            80 * 60 * 2);
  EXPECT_EQ(stats.value("fallback_pixels"), stats.value("primary_rays"));
  EXPECT_EQ(stats.value("fallback_pixels"), stats.value("fallback_pixels_outside_outline") +
                                                stats.value("fallback_pixels_inside_outline"));
  EXPECT_GT(stats.value("fallback_pixels_inside_outline"), 0.0);  // the spheres' and the cone's
  EXPECT_GT(stats.value("pixels_spawning_reflection_or_refraction"), 0.0);
  EXPECT_LT(stats.value("fallback_pixels"), 0.1 * 80 * 60 * 2);
  EXPECT_GT(stats.value("pixels_spawning_rays"), 0.0);
  EXPECT_GT(stats.value("item_buffer_tests"), 0.0);

  for (Material& material : scene.materials) material.reflection = material.transmission = 0.0f;
  const Stats matte = render("hybrid", scene, settings).stats;
  EXPECT_EQ(matte.value("pixels_spawning_reflection_or_refraction"), 0.0);
  EXPECT_EQ(matte.value("reflection_rays") + matte.value("refraction_rays"), 0.0);
  EXPECT_GT(matte.value("shadow_rays"), 0.0);
}

// Where the whole image is one surface seen by the item buffer, no primary
// ray searches the scene.
TEST(Hybrid, AnswersEveryPixelOfAWallFromTheItemBuffer) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0.0f, 0.0f, -3.0f), 40, 30);
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f, 0.0f, 1.0f), Vec3(0.0f, 0.0f, -1.0f), 0));
  const Stats stats = render("hybrid", scene, oneSampleAPixel(scene)).stats;
  EXPECT_EQ(stats.value("primary_rays"), 0.0);
  EXPECT_EQ(stats.value("primary_rays_from_item_buffer"), 40 * 30);
  EXPECT_EQ(stats.value("item_buffer_tests"), 40 * 30);
}

}  // namespace
}  // namespace rise
