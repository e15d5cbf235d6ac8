#include "render/render_limits.hpp"

#include <gtest/gtest.h>

#include <string>

#include "algorithms/registry.hpp"
#include "core/memory_budget.hpp"

namespace rise {
namespace {

RenderSettings settingsOf(int width, int height, int samples = 1, int maxDepth = 5) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.sampling.samples = samples;
  settings.sampling.pattern = samples > 1 ? SamplePattern::Jittered : SamplePattern::None;
  settings.maxDepth = maxDepth;
  settings.threads = 2;
  return settings;
}

const Renderer& kWhitted = *findRenderer("ray-tracing");
const Renderer& kZBuffer = *findRenderer("z-buffer");

std::string refusal(const Scene& scene, const RenderSettings& settings, const Renderer& renderer) {
  try {
    checkRenderFits(scene, settings, renderer);
  } catch (const RenderLimitError& error) {
    return error.what();
  }
  return "";
}

TEST(RenderLimits, NeedsGrowWithThePixelsAndTheSamples) {
  const Scene scene;
  const RenderNeeds small = kWhitted.needs(scene, settingsOf(640, 480));
  const RenderNeeds large = kWhitted.needs(scene, settingsOf(1280, 960));
  EXPECT_GT(large.bytes, 3 * small.bytes);
  EXPECT_GT(kZBuffer.needs(scene, settingsOf(640, 480)).bytes, small.bytes);
  EXPECT_EQ(large.rays, 4 * small.rays);
  EXPECT_EQ(kWhitted.needs(scene, settingsOf(640, 480, 16)).rays, 16 * small.rays);
  EXPECT_EQ(kZBuffer.needs(scene, settingsOf(640, 480)).rays, 0.0);
}

TEST(RenderLimits, TheBudgetIsNeverMoreThanTheDocumentedLimit) {
  std::string why;
  const std::uint64_t budget = memoryBudget(&why);
  EXPECT_GT(budget, 0u);
  EXPECT_LE(budget, kMostMemory);
  EXPECT_FALSE(why.empty());
}

TEST(RenderLimits, RefusesAnImageLargerThanTheMemoryNamingItsSize) {
  const Scene scene;
  EXPECT_EQ(refusal(scene, settingsOf(640, 480), kZBuffer), "");
  const std::string message = refusal(scene, settingsOf(32768, 32768), kZBuffer);
  EXPECT_EQ(message.substr(0, 63),
            "a 32768 x 32768 image with 1 sample a pixel needs about 215 GB ")
      << message;
}

TEST(RenderLimits, RefusesRayTreesThatBranchPastTheLimit) {
  Scene scene;
  scene.materials.resize(1);
  scene.materials[0].name = "glass";
  scene.materials[0].reflection = 0.1f;
  scene.materials[0].transmission = 0.9f;
  EXPECT_EQ(refusal(scene, settingsOf(640, 480, 1, 20), kWhitted), "");
  EXPECT_EQ(refusal(scene, settingsOf(640, 480, 1, 64), kZBuffer), "");
  EXPECT_EQ(refusal(scene, settingsOf(640, 480, 1, 64), kWhitted),
            "a 640 x 480 image with 1 sample a pixel and --max-depth 64 may trace up to 5.7e24 "
            "rays (1.8e19 a sample, as material 'glass' both reflects and refracts); expected at "
            "most 1e12 rays: fewer samples, a smaller image or a lower --max-depth");
  scene.materials[0].reflection = 0.0f;  // a path, not a tree
  EXPECT_EQ(refusal(scene, settingsOf(640, 480, 1, 64), kWhitted), "");
}

// Every algorithm that traces rays has them counted against the limit: the
// hybrid's, from each pixel's first hit on, are Whitted's.
TEST(RenderLimits, CountsTheRaysOfEveryAlgorithmThatTracesThem) {
  Scene scene;
  scene.materials.resize(1);
  scene.materials[0].reflection = 0.1f;
  scene.materials[0].transmission = 0.9f;
  RenderSettings settings = settingsOf(640, 480, 1, 64);
  // The path tracer's paths do not branch: only its many samples pass the limit.
  settings.progression.samples = kMostSamples;
  for (const Renderer* renderer : allRenderers()) {
    const bool tracesRays = renderer->description().reads(Option::MaxDepth);
    EXPECT_EQ(renderer->needs(scene, settings).rays > 0.0, tracesRays) << renderer->name();
    EXPECT_EQ(refusal(scene, settings, *renderer).empty(), !tracesRays) << renderer->name();
  }
  EXPECT_EQ(findRenderer("hybrid")->needs(scene, settings).rays,
            kWhitted.needs(scene, settings).rays);
}

TEST(RenderLimits, RefusesMoreThreadsThanTheLimit) {
  RenderSettings settings = settingsOf(64, 48);
  settings.threads = kMostThreads + 1;
  EXPECT_EQ(refusal(Scene(), settings, kWhitted), "--threads 257: expected at most 256 threads");
}

TEST(RenderLimits, RefusesWorkingMemoryBeyondTheBudgetNamingWhatItIs) {
  EXPECT_NO_THROW(checkWorkingMemoryFits(1000, "the lists", "fewer"));
  try {
    checkWorkingMemoryFits(memoryBudget() + 1, "the lists", "fewer of them");
    ADD_FAILURE() << "no refusal";
  } catch (const RenderLimitError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.substr(0, 27), "the lists would take about ") << message;
    EXPECT_NE(message.find("; expected fewer of them"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace rise
