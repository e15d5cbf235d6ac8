// The original RISE report's classic scene, rendered whole: against a stored
// reference image, and the same whatever the number of threads.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"
#include "io/scene_file.hpp"

namespace rise {
namespace {

RenderResult renderClassic(int width, int height, int threads) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.threads = threads;
  RenderObserver observer;
  return findRenderer("ray-tracing")->render(scene, settings, observer);
}

// The image as it would be stored: 8-bit sRGB values.
int storedValue(float linear) {
  return static_cast<int>(std::lround(srgbFromLinear(std::clamp(linear, 0.0f, 1.0f)) * 255.0f));
}

// The reference was rendered by this ray tracer and checked by eye: visible
// shadows, the mirror sphere's reflections, the floor seen upside down
// through the glass sphere. Rounding may move a few values by a level or two
// between compilers; a change of the algorithm moves many.
TEST(ClassicScene, MatchesTheStoredReference) {
  const Image reference = readImage(std::string(RISE_TEST_DATA) + "/classic-160x120.png");
  const Image image = renderClassic(160, 120, 2).image;
  ASSERT_EQ(image.width(), reference.width());
  ASSERT_EQ(image.height(), reference.height());

  int differing = 0;
  double totalDifference = 0.0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      for (int channel = 0; channel < 3; ++channel) {
        const int difference = std::abs(storedValue(image.at(x, y)[channel]) -
                                        storedValue(reference.at(x, y)[channel]));
        totalDifference += difference;
        if (difference > 2) ++differing;
      }
    }
  }
  const int values = image.width() * image.height() * 3;
  EXPECT_LT(totalDifference / values, 0.05) << "mean difference in 8-bit levels";
  EXPECT_LE(differing, values / 1000) << "values differing by more than 2 levels";
}

TEST(ClassicScene, IsTheSameWhateverTheThreadCount) {
  const RenderResult one = renderClassic(96, 72, 1);
  for (int threads : {2, 3, 7}) {
    const RenderResult many = renderClassic(96, 72, threads);
    EXPECT_EQ(one.image.pixels(), many.image.pixels()) << threads << " threads";
    EXPECT_EQ(one.buffers.at("cost").pixels(), many.buffers.at("cost").pixels());
    EXPECT_EQ(one.stats.value("intersection_tests"), many.stats.value("intersection_tests"));
  }
}

}  // namespace
}  // namespace rise
