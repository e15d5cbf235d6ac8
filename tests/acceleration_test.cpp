// The classic scene rendered with every acceleration structure: the same
// image, to the bit, whichever one finds the hits; only the cost differs.
#include <gtest/gtest.h>

#include "algorithms/registry.hpp"
#include "io/scene_file.hpp"
#include "ray/accelerator.hpp"

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

}  // namespace
}  // namespace rise
