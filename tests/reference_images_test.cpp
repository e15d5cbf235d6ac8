// Every example with every algorithm draws the image it drew when its
// reference was stored (tests/data/references/): a change to how RISE is
// built inside, that should change nothing a user sees, is caught wherever it
// changes a pixel. The renders are small (80 pixels wide, at most 16 samples
// of the scene's own pattern) and compared as a viewer sees them, in 8-bit
// sRGB levels: a compiler that rounds differently (the sanitized build's)
// may move a level here and there, never more.
//
// A change that is meant to change an image stores the new references:
//   RISE_STORE_REFERENCES=1 build/tests/rise_tests --gtest_filter='References*'
// and the commit shows them, one PNG an example and algorithm.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/image_io.hpp"
#include "io/scene_file.hpp"
#include "support/example_testing.hpp"
#include "support/image_agreement_testing.hpp"

namespace rise {
namespace {

using namespace example_testing;
using image_agreement_testing::levelDifference;

constexpr int kWidth = 80;
constexpr int kMostSamples = 16;
// Pixels that may differ by more than a level: a compiler's rounding may
// tip a choice at an edge, and a Monte Carlo sample with it.
constexpr double kMostPixelsApart = 0.005;

const std::filesystem::path kReferences = std::filesystem::path(RISE_TEST_DATA) / "references";

std::filesystem::path referenceOf(const std::string& scene, std::string_view algorithm) {
  return kReferences / (scene.substr(0, scene.find('.')) + "-" + std::string(algorithm) + ".png");
}

RenderSettings referenceSettings(const Scene& scene) {
  RenderRequest request;
  request.image.width = kWidth;
  request.image.samples = std::min(scene.image.sampling.samples, kMostSamples);
  request.settings.threads = 2;
  return settingsFor(scene, request);
}

// The image as a PNG stores it: each channel rounded to its 8-bit level.
Image asStored(const Image& image) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("rise-reference-" + std::to_string(::getpid()) + ".png");
  writeImage(image, file);
  Image stored = readImage(file);
  std::filesystem::remove(file);
  return stored;
}

class References : public testing::TestWithParam<std::string> {};

TEST_P(References, EveryAlgorithmDrawsTheStoredImage) {
#ifdef RISE_SANITIZED_BUILD
  // The sanitized build renders every example with every algorithm in
  // examples_test.cpp; its compiler's images are held to the references by
  // the unsanitized build's.
  GTEST_SKIP() << "the unsanitized build compares the references";
#endif
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + GetParam());
  const RenderSettings settings = referenceSettings(scene);
  const bool store = std::getenv("RISE_STORE_REFERENCES") != nullptr;
  for (const Renderer* renderer : allRenderers()) {
    RenderObserver nobody;
    const Image image = renderer->render(scene, settings, nobody).image;
    const std::filesystem::path reference = referenceOf(GetParam(), renderer->name());
    if (store) {
      std::filesystem::create_directories(kReferences);
      writeImage(image, reference);
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(reference))
        << reference << ": no reference; store it with RISE_STORE_REFERENCES=1";
    const Image expected = readImage(reference);
    const Image drawn = asStored(image);
    ASSERT_EQ(drawn.width(), expected.width()) << renderer->name();
    ASSERT_EQ(drawn.height(), expected.height()) << renderer->name();
    int apart = 0, worst = 0;
    for (int y = 0; y < drawn.height(); ++y)
      for (int x = 0; x < drawn.width(); ++x) {
        const int difference = levelDifference(drawn.at(x, y), expected.at(x, y));
        apart += difference > 1;
        worst = std::max(worst, difference);
      }
    EXPECT_LE(apart, kMostPixelsApart * drawn.width() * drawn.height())
        << renderer->name() << " on " << GetParam() << ": " << apart
        << " pixels differ from the reference by more than a level, by up to " << worst;
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, References, testing::ValuesIn(exampleScenes()), exampleTestName);

}  // namespace
}  // namespace rise
