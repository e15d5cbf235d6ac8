// Every example scene, as a student first meets it: it loads, and every
// algorithm renders it, small, to a finite image that shows more than the
// background, with finite statistics, the same on any number of threads;
// and the four visible-surface algorithms, which share one pipeline, see the
// same polygon at nearly every pixel. A scene added to examples/ is checked
// without a line more here.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/registry.hpp"
#include "io/scene_file.hpp"
#include "support/example_testing.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace example_testing;
using namespace raster_testing;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
// The slowest example at its own size takes some 4 s; a build with
// sanitizers, ten to forty times that: there, the examples are rendered at
// the other sizes only, and the unsanitized build times their own.
#ifdef RISE_SANITIZED_BUILD
constexpr double kSecondsARenderTakes = 120.0;
constexpr bool kAtTheExamplesOwnSize = false;
#else
constexpr double kSecondsARenderTakes = 20.0;
constexpr bool kAtTheExamplesOwnSize = true;
#endif

int finitePixels(const Image& image) {
  int finite = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      finite += std::isfinite(image.at(x, y).r) && std::isfinite(image.at(x, y).g) &&
                std::isfinite(image.at(x, y).b);
  return finite;
}

int pixelsOtherThan(const Image& image, const Color& background) {
  int other = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      other += glm::any(glm::greaterThan(glm::abs(image.at(x, y) - background), Color(1e-3f)));
  return other;
}

class ExampleScene : public testing::TestWithParam<std::string> {
 protected:
  static Scene load(const std::string& name) {
    return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  }
  // Small, one sample at each pixel's centre: the examples' own
  // anti-aliasing and blur are tested apart.
  static RenderSettings smallSettings(const Scene& scene) {
    RenderRequest request;
    request.image = {kWidth, kHeight, 1, SamplePattern::None, FilterKind::Box, {}};
    return settingsFor(scene, request);
  }
};

TEST_P(ExampleScene, RendersWithEveryAlgorithm) {
  const Scene scene = load(GetParam());
  const RenderSettings settings = smallSettings(scene);
  for (const Renderer* renderer : allRenderers()) {
    const RenderResult result = render(renderer->name(), scene, settings);
    EXPECT_EQ(finitePixels(result.image), kWidth * kHeight) << renderer->name();
    EXPECT_GT(pixelsOtherThan(result.image, scene.image.background), kWidth * kHeight / 10)
        << renderer->name();
    for (const auto& [name, value] : result.stats.entries())
      EXPECT_TRUE(std::isfinite(value)) << renderer->name() << "'s " << name << " is " << value;
  }
}

// Its own size and others, wide, tall and tiny: a scene that one algorithm
// orders in a second at one size must not take it minutes at another (depth
// sort's splits once never settled at some sizes). One sample a pixel, as
// the examples' many samples only repeat the same work.
TEST_P(ExampleScene, RendersWithEveryAlgorithmAtEverySizeInSeconds) {
  const Scene scene = load(GetParam());
  std::vector<std::pair<int, int>> sizes{{160, 120}, {257, 31}, {29, 191}, {7, 5}};
  if (kAtTheExamplesOwnSize) sizes.emplace_back(scene.image.width, scene.image.height);
  for (const auto& [width, height] : sizes) {
    RenderRequest request;
    request.image = {width, height, 1, SamplePattern::None, FilterKind::Box, {}};
    const RenderSettings settings = settingsFor(scene, request);
    for (const Renderer* renderer : allRenderers()) {
      const auto start = std::chrono::steady_clock::now();
      const RenderResult result = render(renderer->name(), scene, settings);
      const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
      const std::string label = std::string(renderer->name()) + " at " + std::to_string(width) +
                                " x " + std::to_string(height);
      EXPECT_EQ(finitePixels(result.image), width * height) << label;
      EXPECT_LT(seconds.count(), kSecondsARenderTakes) << label;
    }
  }
}

// The statistics that count work, not the time it took.
std::vector<std::pair<std::string, double>> counters(const Stats& stats) {
  std::vector<std::pair<std::string, double>> counted;
  for (const auto& [name, value] : stats.entries())
    if (!name.ends_with("seconds") && !name.ends_with("per_second"))
      counted.emplace_back(name, value);
  return counted;
}

// The tasks a render is cut into are combined in their order, whichever
// thread drew them, and each pixel's random samples are drawn from its own
// seed: the image and the counters are the same on any number of threads.
TEST_P(ExampleScene, IsTheSameWithEveryAlgorithmOnAnyNumberOfThreads) {
  const Scene scene = load(GetParam());
  RenderRequest request;
  request.image = {kWidth, kHeight, 4, SamplePattern::Jittered, FilterKind::Box, {}};
  RenderSettings settings = settingsFor(scene, request);
  for (const Renderer* renderer : allRenderers()) {
    settings.threads = 1;
    const RenderResult one = render(renderer->name(), scene, settings);
    settings.threads = 3;
    const RenderResult three = render(renderer->name(), scene, settings);
    EXPECT_EQ(one.image.pixels(), three.image.pixels()) << renderer->name();
    EXPECT_EQ(counters(one.stats), counters(three.stats)) << renderer->name();
  }
}

// Pixel centres on an edge may go to either polygon through rounding, and
// depth sort's splits add edges of their own: a few pixels in a hundred at
// most. (Images, not face numbers, are compared: where a model has two
// coplanar faces, the algorithms may show either, to the same effect.) All
// of them blend transparent surfaces alike.
TEST_P(ExampleScene, LooksTheSameToEveryVisibleSurfaceAlgorithm) {
  const Scene scene = load(GetParam());
  const RenderSettings settings = smallSettings(scene);
  const RenderResult first = render(kAlgorithms[0], scene, settings);
  for (std::string_view algorithm : kAlgorithms)
    EXPECT_LE(pixelsDiffering(render(algorithm, scene, settings).image, first.image),
              kWidth * kHeight / 100)
        << algorithm << " against " << kAlgorithms[0];
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleScene, testing::ValuesIn(exampleScenes()),
                         exampleTestName);

}  // namespace
}  // namespace rise
