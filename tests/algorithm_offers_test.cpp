// The front ends ask each algorithm what it offers and needs, rather than
// judge it by its family: the limits count the rays of every algorithm that
// traces them, `rise validate` asks every registered algorithm and names
// those that would refuse, `rise inspect` accepts every algorithm that
// records ray trees, and the statistics of a render cut into tiles are those
// of the whole render, whichever way the algorithm's tiles count.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "core/text.hpp"
#include "io/scene_file.hpp"
#include "render/tile_statistics.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

// A glass that both reflects and refracts, each of its hits spawning two
// rays down to the maximum depth, in an image of 16 million pixels of 4,096
// samples each: some 4e12 rays, which no ray tracer is let trace; the
// visible-surface algorithms trace none and render it.
constexpr const char* kTooManyRays = R"(image: {width: 4000, height: 4000, samples: 4096}
camera: {position: [0, 0, -5], look_at: [0, 0, 0]}
lights: [{point: {position: [0, 5, -5]}}, {point: {position: [0, -5, -5]}}]
materials: {glass: {color: [1, 1, 1], reflection: 0.1, transmission: 0.9, ior: 1.5}}
objects: [{sphere: {center: [0, 0, 0], radius: 1, material: glass}}]
)";

class AlgorithmOffers : public RiseCommand {
 protected:
  std::string tooManyRays() const {
    std::ofstream(file("rays.yaml")) << kTooManyRays;
    return file("rays.yaml").string();
  }
};

std::vector<std::string_view> namesWhere(bool (*wanted)(const AlgorithmDescription&)) {
  std::vector<std::string_view> names;
  for (const Renderer* renderer : allRenderers())
    if (wanted(renderer->description())) names.push_back(renderer->name());
  return names;
}

bool tracesRays(const AlgorithmDescription& algorithm) { return algorithm.reads(Option::MaxDepth); }
bool tracesNoRays(const AlgorithmDescription& algorithm) { return !tracesRays(algorithm); }

TEST_F(AlgorithmOffers, ValidateNamesTheAlgorithmsThatWouldRefuseAndThoseThatWouldNot) {
  const CommandResult result = runRise("validate " + tooManyRays());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find("loads, but not every algorithm would render it"), std::string::npos)
      << result.output;
  // Those whose refusals say the same are named together.
  for (const std::string_view name : namesWhere(tracesRays)) {
    const std::size_t line = result.output.find(std::string(name));
    ASSERT_NE(line, std::string::npos) << name << "\n" << result.output;
    EXPECT_EQ(result.output.find(": a 4000 x 4000 image", line),
              result.output.find_first_of(':', line))
        << name << "\n"
        << result.output;
  }
  EXPECT_NE(result.output.find("  " + joined(namesWhere(tracesNoRays)) + ": would render it"),
            std::string::npos)
      << result.output;
}

// Each command that renders refuses, before it starts, what the algorithm
// it renders with would refuse: the hybrid's rays too.
TEST_F(AlgorithmOffers, EveryAlgorithmThatTracesRaysHasThemCountedBeforeItRenders) {
  const std::string scene = tooManyRays();
  for (const std::string_view algorithm : namesWhere(tracesRays)) {
    const std::string a = " -a " + std::string(algorithm);
    for (const std::string& command : {"render " + scene + a + " -o " + file("x.png").string(),
                                       "explain " + scene + a + " -o " + file("steps").string(),
                                       "inspect " + scene + a + " --pixel 0,0"}) {
      const CommandResult result = runRise(command);
      EXPECT_EQ(result.status, 2) << command << "\n" << result.output;
      EXPECT_NE(result.output.find("may trace up to"), std::string::npos) << command << "\n"
                                                                          << result.output;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(file("x.png")));
  EXPECT_FALSE(std::filesystem::exists(file("steps")));
}

TEST_F(AlgorithmOffers, InspectTakesEveryAlgorithmThatRecordsRayTreesAndNamesThem) {
  std::vector<std::string_view> withTrees;
  for (const Renderer* renderer : renderersOffering(Look::RayTrees))
    withTrees.push_back(renderer->name());
  EXPECT_EQ(withTrees, (std::vector<std::string_view>{"ray-tracing", "distributed-ray-tracing",
                                                      "hybrid", "path-tracing"}));
  for (const std::string_view algorithm : withTrees) {
    const CommandResult result = runRise("inspect " + example("classic.yaml") +
                                         " --width 64 --pixel 32,24 -a " + std::string(algorithm));
    EXPECT_EQ(result.status, 0) << algorithm << "\n" << result.output;
  }
  const CommandResult refused =
      runRise("inspect " + example("classic.yaml") + " --width 64 --pixel 32,24 -a z-buffer");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.output.find("expected one of " + joined(withTrees)), std::string::npos)
      << refused.output;
  EXPECT_NE(runRise("inspect --help").output.find(joined(withTrees)), std::string::npos);
}

// The counters of four tiles, combined as the algorithm's description says
// they combine, are those of the image rendered whole.
TEST(TileStatistics, CombineIntoTheWholeRendersForEveryAlgorithm) {
  const Scene scene = loadSceneFile(example("classic.yaml"));
  RenderRequest request;
  request.image.width = 64;
  request.settings.threads = 2;
  const RenderSettings whole = settingsFor(scene, request);
  for (const Renderer* renderer : allRenderers()) {
    RenderObserver nobody;
    const Stats expected = renderer->render(scene, whole, nobody).stats;
    std::vector<Stats> tiles;
    // Along the ray tracers' tiles of 16 pixels, as rise-mpi cuts them.
    for (const PixelRect& area : {PixelRect{0, 0, 32, 32}, PixelRect{32, 0, 64, 32},
                                  PixelRect{0, 32, 32, 48}, PixelRect{32, 32, 64, 48}}) {
      RenderSettings tile = whole;
      tile.region = area;
      tiles.push_back(renderer->render(scene, tile, nobody).stats);
    }
    const Stats combined = combinedTileStats(renderer->description(), tiles, 1.0);
    for (const auto& [name, value] : expected.entries()) {
      if (name.find("seconds") != std::string::npos || name.ends_with("_per_second") ||
          name.starts_with("accel_") || name.starts_with("bvh_") || name == "noise")
        continue;  // times, what the structure built, which the tiles' rays decide, and the
                   // noise, which is the noisiest tile's
      EXPECT_DOUBLE_EQ(combined.value(name), value) << renderer->name() << ": " << name;
    }
  }
}

}  // namespace
}  // namespace rise
