// The classic scene rendered with every acceleration structure: the same
// image, to the bit, whichever one finds the hits; only the cost differs.
// The Cornell box too, whose floor and walls lie in the planes of the axes.
#include <gtest/gtest.h>

#include "algorithms/registry.hpp"
#include "io/scene_file.hpp"
#include "ray/accelerator.hpp"
#include "scene/camera.hpp"

namespace rise {
namespace {

RenderResult renderClassic(Accel accel) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.threads = 2;
  settings.accel = accel;
  RenderObserver observer;
  return findRenderer("ray-tracing")->render(scene, settings, observer);
}

TEST(Acceleration, RendersTheClassicSceneAsBruteForceDoes) {
  const RenderResult bruteForce = renderClassic(Accel::None);
  for (Accel accel : availableAccels()) {
    const RenderResult result = renderClassic(accel);
    EXPECT_EQ(result.image.pixels(), bruteForce.image.pixels()) << accelName(accel);
    EXPECT_EQ(result.buffers.at("depth").pixels(), bruteForce.buffers.at("depth").pixels())
        << accelName(accel);
    EXPECT_EQ(result.buffers.at("normal").pixels(), bruteForce.buffers.at("normal").pixels())
        << accelName(accel);
    EXPECT_EQ(result.stats.value("rays"), bruteForce.stats.value("rays")) << accelName(accel);
  }
}

// Brute force tests every shape for each ray; the BVH tests a few, and
// counts the boxes it opened to find them.
TEST(Acceleration, TheBvhTestsFewerPrimitivesAndCountsItsBoxes) {
  const RenderResult bruteForce = renderClassic(Accel::None);
  const RenderResult bvh = renderClassic(Accel::Bvh);
  EXPECT_LT(bvh.stats.value("intersection_tests_per_ray"),
            0.5 * bruteForce.stats.value("intersection_tests_per_ray"));
  EXPECT_EQ(bruteForce.stats.value("nodes_visited"), 0.0);
  EXPECT_GT(bvh.stats.value("nodes_visited_per_ray"), 1.0);
  EXPECT_GE(bvh.stats.value("accel_build_seconds"), 0.0);
}

// The Cornell box's floor is a square in the plane y = 0, split along its
// diagonal: some rays meet both halves at the same t. Every structure keeps
// the first in the model's order, though the BVH's boxes of the two halves
// have no height: one ray at a time, and the primary rays of a grid of
// samples in packets. (Embree keeps whichever it meets first.)
TEST(Acceleration, RendersTheCornellBoxAsBruteForceDoes) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box.yaml");
  RenderSettings settings;
  settings.width = 64;
  settings.height = 64;
  settings.threads = 2;
  settings.sampling.samples = 9;
  const auto render = [&](Accel accel) {
    settings.accel = accel;
    RenderObserver observer;
    return findRenderer("ray-tracing")->render(scene, settings, observer);
  };
  settings.sampling.pattern = SamplePattern::Regular;
  const RenderResult bruteForce = render(Accel::None);
  for (Accel accel : {Accel::Spheres, Accel::Bvh}) {
    const RenderResult result = render(accel);
    EXPECT_EQ(result.image.pixels(), bruteForce.image.pixels()) << accelName(accel);
    EXPECT_EQ(result.buffers.at("normal").pixels(), bruteForce.buffers.at("normal").pixels())
        << accelName(accel);
  }
  // The same rays one at a time.
  const ViewFrame view(scene.camera, settings.width, settings.height);
  const auto bruteForceHits = buildAccelerator(Accel::None, scene.shapes);
  const auto bvh = buildAccelerator(Accel::Bvh, scene.shapes);
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      for (int sample = 0; sample < settings.sampling.samples; ++sample) {
        const Ray ray = view.primaryRay(static_cast<float>(x) + (sample % 3 + 0.5f) / 3.0f,
                                        static_cast<float>(y) + (sample / 3 + 0.5f) / 3.0f);
        Hit expected, actual;
        IntersectionCounters counters;
        ASSERT_EQ(bvh->nearest(ray, 0.0f, actual, counters),
                  bruteForceHits->nearest(ray, 0.0f, expected, counters));
        EXPECT_EQ(actual.primitive, expected.primitive) << x << "," << y << " sample " << sample;
      }
    }
  }
}

}  // namespace
}  // namespace rise
