// What distributed ray tracing must do (Cook, Porter & Carpenter 1984), each
// effect measured on small images with an answer known in advance: sharp
// where in focus, blurred by the motion, penumbrae as wide as the light, and
// anti-aliasing whose error shrinks as the sampling improves.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "algorithms/registry.hpp"
#include "core/image_error.hpp"
#include "io/scene_file.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

RenderResult render(const std::string& sceneText, const std::string& algorithm,
                    PixelSampling sampling, std::uint64_t seed = 0, int threads = 2) {
  const Scene scene = loadScene(sceneText, "test.yaml");
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.sampling = sampling;
  settings.seed = seed;
  settings.threads = threads;
  RenderObserver observer;
  return findRenderer(algorithm)->render(scene, settings, observer);
}

PixelSampling jittered(int samples) { return {samples, SamplePattern::Jittered}; }

// How many pixels of row y are strictly between 10% and 90% of `full`.
int transitionWidth(const Image& image, int y, float full = 1.0f) {
  int width = 0;
  for (int x = 0; x < image.width(); ++x) {
    const float value = image.at(x, y).r / full;
    if (value > 0.1f && value < 0.9f) ++width;
  }
  return width;
}

// A camera on the -z axis, 5 units from the origin, and lights-free white
// surfaces: everything seen is exactly 1, the background 0.
std::string flatScene(const std::string& camera, const std::string& objects, int width = 64,
                      int height = 64) {
  return "image: {width: " + std::to_string(width) + ", height: " + std::to_string(height) +
         ", background: [0, 0, 0]}\n"
         "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 40" +
         camera +
         "}\n"
         "ambient: [1, 1, 1]\n"
         "materials: {white: {color: [1, 1, 1], ka: 1, kd: 0}}\n"
         "objects:\n" +
         objects;
}

// A wall filling the image's left half (+x is to the left), at depth z.
std::string halfWall(float z) {
  const std::string zs = std::to_string(z);
  return "  - polygon: {vertices: [[0, -50, " + zs + "], [50, -50, " + zs + "], [50, 50, " + zs +
         "], [0, 50, " + zs + "]], material: white}\n";
}

TEST(DistributedRayTracing, WithoutItsEffectsMatchesWhittedRayTracing) {
  const std::string classic = std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml";
  Scene scene = loadSceneFile(classic);
  RenderSettings settings;
  settings.width = 80;
  settings.height = 60;
  settings.sampling = jittered(4);
  RenderObserver observer;
  const Image whitted = findRenderer("ray-tracing")->render(scene, settings, observer).image;
  const Image cook =
      findRenderer("distributed-ray-tracing")->render(scene, settings, observer).image;
  EXPECT_LT(rmse(whitted, cook), 1e-6);
}

TEST(DistributedRayTracing, TheFocalPlaneIsSharpAndFarPlanesBlur) {
  const std::string lens = ", aperture: 0.5, focal_distance: 5";
  const Image inFocus =
      render(flatScene(lens, halfWall(0.0f)), "distributed-ray-tracing", jittered(64)).image;
  const Image farAway =
      render(flatScene(lens, halfWall(10.0f)), "distributed-ray-tracing", jittered(64)).image;
  // The circle of confusion of the far wall: 0.5 (15 - 5) / 15 units on the
  // focal plane, 17.6 pixels a unit there: about 6 pixels across.
  EXPECT_LE(transitionWidth(inFocus, 32), 1);
  EXPECT_GE(transitionWidth(farAway, 32), 3);
  EXPECT_LE(transitionWidth(farAway, 32), 7);
}

// The sphere's streak: the columns of the middle row that it covers at some
// instant.
int streakLength(float motion) {
  const std::string sphere =
      "  - sphere: {center: [0, 0, 0], radius: 0.5, material: white,\n"
      "             motion: {translate: [" +
      std::to_string(motion) + ", 0, 0]}}\n";
  const Image image = render(flatScene(", shutter: [0, 1]", sphere, 128, 64),
                             "distributed-ray-tracing", jittered(64))
                          .image;
  int length = 0;
  for (int x = 0; x < image.width(); ++x)
    if (image.at(x, 32).r > 0.02f) ++length;
  return length;
}

TEST(DistributedRayTracing, MotionBlurFollowsTheMotion) {
  // 17.6 pixels a unit at the sphere's distance.
  const int still = streakLength(0.0f);
  EXPECT_NEAR(still, 17.6, 2.0);
  EXPECT_NEAR(streakLength(1.0f) - still, 17.6, 3.0);
  EXPECT_NEAR(streakLength(2.0f) - still, 35.2, 3.0);
}

// A wall facing the camera, lit from the side by a ball of light; a sheet
// seen edge-on (it contains the camera) shadows the wall from x = 2.5 on.
// The penumbra's width grows with the light's radius: about 0.4 units on the
// wall for a radius of 0.2, 8.8 pixels a unit there.
int penumbraWidth(float lightRadius) {
  const std::string head =
      "image: {width: 64, height: 64, background: [0, 0, 0]}\n"
      "camera: {position: [0, 0, -5], look_at: [0, 0, 5], fov: 40}\n"
      "lights: [{sphere: {center: [-5, 0, 2], radius: " +
      std::to_string(lightRadius) +
      "}}]\n"
      "materials: {wall: {ka: 0, kd: 1}}\n"
      "objects:\n"
      "  - plane: {point: [0, 0, 5], normal: [0, 0, -1], material: wall}\n";
  const std::string sheet =
      "  - polygon: {vertices: [[0, -50, 2.5], [0, -50, 4], [0, 50, 4], [0, 50, 2.5]], "
      "material: wall}\n";
  const Image lit = render(head, "distributed-ray-tracing", jittered(256)).image;
  const Image shadowed = render(head + sheet, "distributed-ray-tracing", jittered(256)).image;
  int width = 0;
  for (int x = 0; x < lit.width(); ++x) {
    const float visible = shadowed.at(x, 32).r / lit.at(x, 32).r;
    if (visible > 0.1f && visible < 0.9f) ++width;
  }
  return width;
}

TEST(DistributedRayTracing, PenumbraWidensWithTheLightsSize) {
  const int small = penumbraWidth(0.2f);
  const int large = penumbraWidth(1.0f);
  EXPECT_NEAR(small, 3.5, 2.0);
  EXPECT_GT(large, 3 * small);
}

// A slanted edge: white above a line at 30 degrees, black below.
std::string slantedEdge() {
  return flatScene("",
                   "  - polygon: {vertices: [[-10, 0, 0], [10, 0, 0], [10, 10, 0]], "
                   "material: white, transform: {rotate: [0, 0, 30], translate: [0.1, 0, 0]}}\n",
                   32, 32);
}

const Image& slantedEdgeReference() {
  static const Image reference = render(slantedEdge(), "ray-tracing", jittered(1024)).image;
  return reference;
}

double slantedEdgeError(PixelSampling sampling, std::uint64_t seed) {
  return rmse(render(slantedEdge(), "ray-tracing", sampling, seed).image, slantedEdgeReference());
}

TEST(AntiAliasing, ShrinksTheErrorOnASlantedEdge) {
  const double aliased = slantedEdgeError({}, 0);
  EXPECT_GT(aliased, 0.05);
  EXPECT_LT(slantedEdgeError(jittered(16), 0), 0.4 * aliased);
  PixelSampling adaptive{16, SamplePattern::Adaptive};
  EXPECT_LT(slantedEdgeError(adaptive, 0), 0.5 * aliased);
}

// The visible-surface algorithms anti-alias by accumulation: whole frames
// at jittered sub-pixel offsets, filtered like the ray tracers' samples.
TEST(AntiAliasing, AppliesToTheVisibleSurfaceAlgorithms) {
  for (const std::string_view name : raster_testing::visibleSurfaceAlgorithms()) {
    const std::string algorithm(name);
    const double aliased = rmse(render(slantedEdge(), algorithm, {}).image, slantedEdgeReference());
    const RenderResult smooth = render(slantedEdge(), algorithm, jittered(16));
    EXPECT_LT(rmse(smooth.image, slantedEdgeReference()), 0.4 * aliased) << algorithm;
    EXPECT_EQ(smooth.stats.value("samples_per_pixel"), 16) << algorithm;
  }
}

TEST(AntiAliasing, JitteredBeatsRandomAtTheSameCount) {
  double jitteredError = 0.0, randomError = 0.0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    jitteredError += slantedEdgeError(jittered(16), seed);
    randomError += slantedEdgeError({16, SamplePattern::Random}, seed);
  }
  EXPECT_LT(jitteredError, 0.75 * randomError);
}

TEST(AntiAliasing, AdaptiveRefinesOnlyWhereCornersDiffer) {
  const PixelSampling adaptive{16, SamplePattern::Adaptive};
  const RenderResult edge = render(slantedEdge(), "ray-tracing", adaptive);
  const double refined = edge.stats.value("adaptive_refined_pixels");
  EXPECT_GT(refined, 20);           // about one pixel a row along the edge
  EXPECT_LT(refined, 32 * 32 / 5);  // and nothing away from it
  const RenderResult empty = render(flatScene("", "  []\n", 16, 16), "ray-tracing", adaptive);
  EXPECT_EQ(empty.stats.value("adaptive_refined_pixels"), 0);
}

TEST(AntiAliasing, TheSameSeedGivesTheSameImageOnAnyThreadCount) {
  const std::string scene = std::string(RISE_SOURCE_DIR) + "/examples/soft-shadows.yaml";
  Scene loaded = loadSceneFile(scene);
  RenderSettings settings;
  settings.width = 48;
  settings.height = 30;
  settings.sampling = jittered(4);
  RenderObserver observer;
  const Renderer& cook = *findRenderer("distributed-ray-tracing");
  settings.threads = 1;
  const Image one = cook.render(loaded, settings, observer).image;
  settings.threads = 3;
  EXPECT_EQ(one.pixels(), cook.render(loaded, settings, observer).image.pixels());
  settings.seed = 99;
  EXPECT_NE(one.pixels(), cook.render(loaded, settings, observer).image.pixels());
}

}  // namespace
}  // namespace rise
