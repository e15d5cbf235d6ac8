// What the step players say of the steps they do not show: the counts "so
// far" are of every step, kept or not, so that the last step of a thinned
// record says every pixel is final; Warnock's windows are thinned level by
// level, so that every level of the quadtree shows, the large windows kept
// whole; and the scanline's step at a band's first row says why every edge
// crossing it enters there.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"
#include "render/step_recorder.hpp"

namespace rise {
namespace {

class Recording final : public RenderObserver {
 public:
  explicit Recording(StepBudget budget = {}) : recorder(std::move(budget)) {}
  StepRecorder* stepRecorder() override { return &recorder; }
  StepRecorder recorder;
};

Scene classic() { return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml"); }

RenderSettings sized(const Scene& scene, int width, int height) {
  RenderRequest request;
  request.image.width = width;
  request.image.height = height;
  return settingsFor(scene, request);
}

TEST(StepPlayerCounts, AreOfEveryStepKeptOrNot) {
  StepRecorder recorder;
  for (int i = 0; i < 1000; ++i) {
    Step step(i % 2 ? "odd" : "even", "a step");
    step.settled.push_back({i, 0, i + 1, 2});
    step.writes.push_back({i, 0, Color(1.0f), 0, 0.0f, i % 10 != 0});
    recorder.record(std::move(step), i);
  }
  const std::vector<Step> kept = recorder.keptSteps();
  ASSERT_LT(kept.size(), 300u);
  const StepTally& last = kept.back().soFar;
  EXPECT_EQ(last.settled, 2000u);
  EXPECT_EQ(last.painted, 900u);
  EXPECT_EQ(last.hidden, 100u);
  EXPECT_EQ(last.kinds,
            (std::vector<std::pair<std::string, std::uint64_t>>{{"even", 500}, {"odd", 500}}));
  EXPECT_EQ(kept[1].soFar.settled, 2u * (static_cast<std::uint64_t>(kept[1].skippedBefore) + 2));
}

TEST(StepPlayerCounts, TheLastStepOfEveryAlgorithmHasSettledTheWholeImage) {
  const Scene scene = classic();
  for (const auto& [width, height] : {std::pair{96, 72}, std::pair{50, 130}}) {
    const RenderSettings settings = sized(scene, width, height);
    for (const std::string_view algorithm : {"scanline", "area-subdivision", "ray-tracing"}) {
      Recording recording;
      findRenderer(algorithm)->render(scene, settings, recording);
      const std::vector<Step> kept = recording.recorder.keptSteps();
      EXPECT_EQ(kept.back().soFar.settled, static_cast<std::uint64_t>(width * height))
          << algorithm << " at " << width << " x " << height;
    }
  }
}

TEST(StepPlayerCounts, WarnocksWindowsShowEveryLevelTheLargeOnesWhole) {
  const Scene scene = classic();
  Recording all({.every = 1});
  Recording thinned;
  const RenderSettings settings = sized(scene, 320, 240);
  findRenderer("area-subdivision")->render(scene, settings, all);
  findRenderer("area-subdivision")->render(scene, settings, thinned);
  const auto levels = [](const std::vector<Step>& steps) {
    std::map<double, int> count;
    for (const Step& step : steps)
      for (const auto& [name, value] : step.values)
        if (name == "level") ++count[value];
    return count;
  };
  const std::map<double, int> every = levels(all.recorder.keptSteps());
  const std::vector<Step> kept = thinned.recorder.keptSteps();
  const std::map<double, int> shown = levels(kept);
  EXPECT_LE(kept.size(), static_cast<std::size_t>(StepBudget::kDefaultKeptSteps) + 1);
  ASSERT_EQ(shown.size(), every.size()) << "a level of the quadtree shows no window";
  for (const double level : {0.0, 1.0, 2.0}) EXPECT_EQ(shown.at(level), every.at(level)) << level;
}

TEST(StepPlayerCounts, TheScanlineSaysWhyEdgesEnterAtABandsFirstRow) {
  const Scene scene = classic();
  Recording recording({.every = 1});
  findRenderer("scanline")->render(scene, sized(scene, 160, 120), recording);
  int bandStarts = 0;
  for (const Step& step : recording.recorder.keptSteps()) {
    const int row = std::stoi(step.text.substr(std::string("scanline ").size()));
    const bool bandStart = row > 0 && row % 16 == 0;
    bandStarts += bandStart;
    EXPECT_EQ(step.text.find("the first scanline of the band") != std::string::npos, bandStart)
        << step.text;
  }
  EXPECT_EQ(bandStarts, 7);
}

}  // namespace
}  // namespace rise
