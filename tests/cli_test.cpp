// End-to-end tests of the `rise` command: what a user types and sees.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

TEST_F(RiseCommand, RendersTheClassicSceneWithStatsAndBuffers) {
  const CommandResult result = runRise(
      "render " + example("classic.yaml") + " -o " + file("classic.png").string() +
      " --width 64 --threads 2 --aov depth,normal,cost --stats " + file("stats.json").string());
  ASSERT_EQ(result.status, 0) << result.output;

  const Image image = readImage(file("classic.png"));
  EXPECT_EQ(image.width(), 64);
  EXPECT_EQ(image.height(), 48);  // the scene's 4:3 aspect ratio is kept
  for (const char* buffer : {"depth", "normal", "cost"})
    EXPECT_TRUE(fs::exists(file(std::string("classic.") + buffer + ".png"))) << buffer;

  std::ifstream statsFile(file("stats.json"));
  const nlohmann::json stats = nlohmann::json::parse(statsFile);
  EXPECT_EQ(stats["algorithm"], "ray-tracing");
  EXPECT_EQ(stats["width"], 64);
  EXPECT_EQ(stats["threads"], 2);
  EXPECT_EQ(stats["primary_rays"], 64 * 48);
  EXPECT_GT(stats["shadow_rays"].get<double>(), 0.0);
  EXPECT_GT(stats["reflection_rays"].get<double>(), 0.0);
  EXPECT_GT(stats["refraction_rays"].get<double>(), 0.0);
  EXPECT_GT(stats["intersection_tests"].get<double>(), 0.0);
  EXPECT_GT(stats["render_seconds"].get<double>(), 0.0);

  EXPECT_NE(result.output.find("primary_rays"), std::string::npos);  // the report on stderr
  EXPECT_EQ(result.output.find('\r'), std::string::npos);  // no progress bar off a terminal
}

TEST_F(RiseCommand, ReadsTheSceneFromStandardInput) {
  const CommandResult result = runRise("render - -o " + file("piped.ppm").string() +
                                       " --width 32 < " + example("classic.yaml"));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(readImage(file("piped.ppm")).width(), 32);
}

TEST_F(RiseCommand, LinearEncodingWritesRawValues) {
  std::ofstream(file("grey.yaml")) << "image: {width: 4, height: 4, background: [0.5, 0.5, 0.5]}\n"
                                      "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                                      "objects: []\n";
  ASSERT_EQ(
      runRise("render " + file("grey.yaml").string() + " -o " + file("srgb.png").string()).status,
      0);
  ASSERT_EQ(runRise("render " + file("grey.yaml").string() + " -o " + file("linear.png").string() +
                    " --encoding linear")
                .status,
            0);
  EXPECT_NEAR(readImage(file("srgb.png")).at(0, 0).r, 0.5f, 0.003f);
  EXPECT_NEAR(readImage(file("linear.png"), Encoding::Linear).at(0, 0).r, 0.5f, 0.003f);
}

TEST_F(RiseCommand, ASceneErrorExitsWithStatusTwoAndWritesNothing) {
  std::ofstream(file("typo.yaml")) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                                      "materials: {m: {}}\n"
                                      "objects:\n"
                                      "  - sphere: {center: [0, 0, 0], radus: 1, material: m}\n";
  const CommandResult result =
      runRise("render " + file("typo.yaml").string() + " -o " + file("typo.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find(file("typo.yaml").string() + ":4:"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("did you mean 'radius'"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(file("typo.png")));
}

TEST_F(RiseCommand, AMissingSceneFileIsBadInput) {
  const CommandResult result = runRise("render " + file("absent.yaml").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("absent.yaml"), std::string::npos) << result.output;
}

TEST_F(RiseCommand, AnUnknownAlgorithmIsBadInput) {
  const CommandResult result = runRise("render " + example("classic.yaml") + " -a teleport");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("teleport"), std::string::npos) << result.output;
}

// An output that cannot be written is found before the render, as bad input.
TEST_F(RiseCommand, AnOutputInAMissingFolderIsBadInput) {
  const CommandResult result = runRise("render " + example("classic.yaml") + " --width 8 -o " +
                                       file("no/such/folder/x.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("x.png"), std::string::npos) << result.output;
}

TEST_F(RiseCommand, ComparesEveryAlgorithmOnOneScene) {
  const CommandResult result =
      runRise("compare " + example("classic.yaml") + " --width 32 -o " + file("compare").string());
  ASSERT_EQ(result.status, 0) << result.output;
  std::ifstream csvFile(file("compare/results.csv"));
  std::string header;
  std::getline(csvFile, header);
  EXPECT_EQ(header.rfind("algorithm,", 0), 0u) << header;
  EXPECT_NE(header.find("render_seconds"), std::string::npos);
  int rows = 0;
  for (std::string line; std::getline(csvFile, line);) {
    const std::string algorithm = line.substr(0, line.find(','));
    EXPECT_EQ(readImage(file("compare/" + algorithm + ".png")).width(), 32) << algorithm;
    ++rows;
  }
  EXPECT_EQ(rows, static_cast<int>(allRenderers().size()));
  std::ifstream html(file("compare/index.html"));
  const std::string page{std::istreambuf_iterator<char>(html), {}};
  for (const Renderer* renderer : allRenderers()) {
    const std::string algorithm(renderer->name());
    EXPECT_NE(page.find("src=\"" + algorithm + ".png\""), std::string::npos) << algorithm;
  }
  EXPECT_NE(page.find("<svg"), std::string::npos);  // the bar chart of the times
  EXPECT_TRUE(fs::exists(file("compare/results.md")));
}

// results.csv as a table: the algorithm's row, the counter's column.
std::map<std::string, std::map<std::string, std::string>> readResults(const fs::path& csv) {
  const auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::ifstream file(csv);
  std::string line;
  std::getline(file, line);
  const std::vector<std::string> header = split(line);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline(file, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t i = 1; i < cells.size(); ++i) rows[cells[0]][header[i]] = cells[i];
  }
  return rows;
}

TEST_F(RiseCommand, ComparesTheHybridWithTheRayTracerWhoseImageItRenders) {
  const CommandResult result =
      runRise("compare " + example("md2.yaml") + " --width 80 --algorithms ray-tracing,hybrid -o " +
              file("hybrid").string());
  ASSERT_EQ(result.status, 0) << result.output;
  auto rows = readResults(file("hybrid/results.csv"));
  std::map<std::string, std::string>& hybrid = rows["hybrid"];
  EXPECT_LE(std::stoi(hybrid["pixels_differing_from_ray_tracing"]), 4);
  EXPECT_EQ(std::stod(hybrid["intersection_tests_saved"]),
            std::stod(rows["ray-tracing"]["intersection_tests"]) -
                std::stod(hybrid["intersection_tests"]));
  EXPECT_GT(std::stod(hybrid["speedup_over_ray_tracing"]), 0.0);
  for (const char* counter : {"primary_rays_from_item_buffer", "fallback_pixels",
                              "item_buffer_seconds", "ray_pass_seconds"})
    EXPECT_FALSE(hybrid[counter].empty()) << counter;
  EXPECT_TRUE(rows["ray-tracing"]["pixels_differing_from_ray_tracing"].empty());
}

// The pixel of the glass sphere: the hybrid's tree is Whitted's, the primary
// ray's hit taken from the item buffer.
TEST_F(RiseCommand, InspectsAPixelOfTheHybrid) {
  const CommandResult result =
      runRise("inspect " + example("classic.yaml") +
              " --width 160 --samples 1 --pixel 80,55 -a hybrid -o " + file("tree.json").string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("refraction"), std::string::npos) << result.output;
  std::ifstream json(file("tree.json"));
  EXPECT_EQ(nlohmann::json::parse(json)["algorithm"], "hybrid");
}

TEST_F(RiseCommand, ListsTheAlgorithmsWithTheirCitations) {
  const CommandResult result = runRise("algorithms");
  EXPECT_EQ(result.status, 0);
  EXPECT_NE(result.output.find("ray-tracing"), std::string::npos);
  EXPECT_NE(result.output.find("Whitted"), std::string::npos);
}

// Shadow volumes are the scanline's: the other visible-surface algorithms
// refuse them, naming the one that draws them, and write nothing; the ray
// tracers, which do not read --shadows, only note it.
TEST_F(RiseCommand, ShadowVolumesAreTheScanlinesAlone) {
  for (const char* algorithm : {"z-buffer", "depth-sort", "area-subdivision"}) {
    const CommandResult refused =
        runRise("render " + example("classic.yaml") + " --width 32 --shadows volume -a " +
                algorithm + " -o " + file("refused.png").string());
    EXPECT_EQ(refused.status, 2) << algorithm;
    EXPECT_NE(refused.output.find("--shadows volume: " + std::string(algorithm) +
                                  " does not draw these shadows; only scanline does"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(fs::exists(file("refused.png"))) << algorithm;
  }
  const CommandResult compared =
      runRise("compare " + example("classic.yaml") + " --width 32 --shadows volume -o " +
              file("compare").string());
  EXPECT_EQ(compared.status, 2);
  EXPECT_NE(compared.output.find("only scanline does"), std::string::npos) << compared.output;

  const CommandResult counted =
      runRise("render " + example("classic.yaml") + " --width 48 --shadows volume -a scanline -o " +
              file("volumes.png").string() + " --stats " + file("stats.json").string());
  ASSERT_EQ(counted.status, 0) << counted.output;
  std::ifstream statsFile(file("stats.json"));
  const nlohmann::json stats = nlohmann::json::parse(statsFile);
  for (const char* counter : {"shadow_volume_faces", "shadow_volume_tests",
                              "shadow_volume_crossings", "shadowed_pixel_lights"})
    EXPECT_GT(stats[counter].get<double>(), 0.0) << counter;
  EXPECT_EQ(stats["eye_in_volumes"], 0);

  const CommandResult traced =
      runRise("render " + example("classic.yaml") + " --width 32 --shadows volume -o " +
              file("traced.png").string());
  EXPECT_EQ(traced.status, 0) << traced.output;
  EXPECT_NE(traced.output.find("ray-tracing does not read --shadows"), std::string::npos);

  const CommandResult listed = runRise("algorithms");
  EXPECT_NE(listed.output.find("shadows: map, volume"), std::string::npos) << listed.output;
}

TEST_F(RiseCommand, ValidatesWithoutRendering) {
  const CommandResult result = runRise("validate " + example("classic.yaml"));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("ok"), std::string::npos);
}

TEST_F(RiseCommand, AModelFileThatCannotBeReadIsBadInput) {
  // The first 5000 bytes of an MD2 model, which holds 198 keyframes.
  std::ifstream model(example("models/sydney/sydney.md2"), std::ios::binary);
  std::string start(5000, '\0');
  model.read(start.data(), static_cast<std::streamsize>(start.size()));
  std::ofstream(file("cut.md2"), std::ios::binary) << start;
  std::ofstream(file("model.yaml")) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                                       "materials: {m: {}}\n"
                                       "objects:\n"
                                       "  - mesh: {file: cut.md2, material: m}\n";
  const CommandResult result =
      runRise("render " + file("model.yaml").string() + " -o " + file("model.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.output, file("model.yaml").string() +
                               ":4:18: cannot load mesh 'cut.md2': the file is cut short: its 198 "
                               "keyframes should end at byte 288824, but it has 5000 bytes\n");
  EXPECT_FALSE(fs::exists(file("model.png")));
}

// Brute force opens no bounding volume; the BVH opens boxes.
TEST_F(RiseCommand, ChoosesTheAccelerationStructure) {
  for (const std::string accel : {"none", "bvh"}) {
    const CommandResult result =
        runRise("render " + example("classic.yaml") + " -o " + file(accel + ".png").string() +
                " --width 32 --accel " + accel + " --stats " + file(accel + ".json").string());
    ASSERT_EQ(result.status, 0) << result.output;
    const auto stats = nlohmann::json::parse(std::ifstream(file(accel + ".json")));
    EXPECT_GE(stats["accel_build_seconds"].get<double>(), 0.0);
    EXPECT_EQ(stats["nodes_visited"].get<double>() > 0.0, accel == "bvh");
  }

  const CommandResult unknown = runRise("render " + example("classic.yaml") + " -o " +
                                        file("octree.png").string() + " --accel octree");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.output.find("octree"), std::string::npos) << unknown.output;
  EXPECT_FALSE(fs::exists(file("octree.png")));
}

// A Quake II skin whose palette lacks its marker byte is worn, and said.
TEST_F(RiseCommand, PrintsTheWarningsOfFilesReadWithAFix) {
  const fs::path sydney = fs::path(RISE_SOURCE_DIR) / "examples/models/sydney";
  std::ifstream original(sydney / "sydney.pcx", std::ios::binary);
  std::string skin{std::istreambuf_iterator<char>(original), {}};
  skin.erase(skin.size() - 769, 1);
  std::ofstream(file("sydney.pcx"), std::ios::binary) << skin;
  fs::copy_file(sydney / "sydney.md2", file("sydney.md2"));
  std::ofstream(file("skin.yaml")) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                                      "materials: {skin: {}}\n"
                                      "objects: [mesh: {file: sydney.md2, material: skin}]\n";
  const CommandResult result = runRise("validate " + file("skin.yaml").string());
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find(file("skin.yaml").string() +
                               ":3:24: warning: " + file("sydney.pcx").string() +
                               ": the 8-bit PCX image's palette lacks its 0x0C marker byte"),
            std::string::npos)
      << result.output;
}

// Without Embree at build time, asking for it is bad input that says what
// there is instead; with it, it renders.
TEST_F(RiseCommand, SaysWhichStructuresABuildWithoutEmbreeHas) {
  const CommandResult result = runRise("render " + example("classic.yaml") + " -o " +
                                       file("embree.png").string() + " --width 32 --accel embree");
  if (result.status == 0) GTEST_SKIP() << "this build has Embree";
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("available: none, spheres, bvh"), std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(file("embree.png")));
}

}  // namespace
TEST_F(RiseCommand, ExplainWritesAPageOfTheStepsWithAFramePerStep) {
  const CommandResult result = runRise("explain " + example("classic.yaml") +
                                       " -a scanline --width 40 -o " + file("steps").string());
  ASSERT_EQ(result.status, 0) << result.output;
  for (const char* written : {"index.html", "steps.json", "image.png", "frames/0001.png"})
    EXPECT_TRUE(fs::exists(file("steps") / written)) << written;
  std::ifstream stepsFile(file("steps") / "steps.json");
  const nlohmann::json steps = nlohmann::json::parse(stepsFile);
  EXPECT_EQ(steps["algorithm"], "scanline");
  EXPECT_FALSE(steps["steps"].empty());
}

TEST_F(RiseCommand, ExplainDrawsTheStepsShapesOnFramesWhenAsked) {
  const CommandResult result =
      runRise("explain " + example("classic.yaml") +
              " -a area-subdivision --width 40 --shapes -o " + file("steps").string());
  ASSERT_EQ(result.status, 0) << result.output;
  // Warnock's first window is the whole screen, outlined in the window's colour.
  const Image frame = readImage(file("steps") / "frames/0001.png");
  const Image withShapes = readImage(file("steps") / "shapes/0001.png");
  const Color windowColour(1.0f, linearFromSrgb(204.0f / 255.0f), 0.0f);
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{39, 29}, std::pair{20, 0}}) {
    EXPECT_NEAR(withShapes.at(x, y).g, windowColour.g, 1e-3f) << x << "," << y;
    EXPECT_NEAR(withShapes.at(x, y).b, 0.0f, 1e-3f) << x << "," << y;
  }
  EXPECT_EQ(withShapes.at(20, 15), frame.at(20, 15));  // inside, the frame as it was
}

TEST_F(RiseCommand, ExplainRefusesARegionOutsideTheImage) {
  const CommandResult result =
      runRise("explain " + example("classic.yaml") + " --width 40 --region 100,100,5,5 -o " +
              file("steps").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--region 100,100,5,5"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(file("steps")));
}

TEST_F(RiseCommand, InspectPrintsTheRayTreeOfAGlassPixel) {
  const CommandResult result =
      runRise("inspect " + example("classic.yaml") + " --width 64 --pixel 32,24 -o " +
              file("tree.json").string() + " --picture " + file("tree.svg").string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("refraction"), std::string::npos) << result.output;
  EXPECT_TRUE(fs::exists(file("tree.json")));
  EXPECT_TRUE(fs::exists(file("tree.svg")));
}

TEST_F(RiseCommand, InspectRefusesAVisibleSurfaceAlgorithmAndAPixelOutside) {
  const CommandResult raster =
      runRise("inspect " + example("classic.yaml") + " --width 64 --pixel 1,1 -a z-buffer");
  EXPECT_EQ(raster.status, 2);
  EXPECT_NE(raster.output.find("traces no rays"), std::string::npos) << raster.output;
  const CommandResult notSvg =
      runRise("inspect " + example("classic.yaml") + " --width 64 --pixel 1,1 --picture " +
              file("tree.png").string());
  EXPECT_EQ(notSvg.status, 2);
  EXPECT_NE(notSvg.output.find("ending in .svg"), std::string::npos) << notSvg.output;
  const CommandResult outside =
      runRise("inspect " + example("classic.yaml") + " --width 64 --pixel 64,0");
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.output.find("from 0,0 to 63,47"), std::string::npos) << outside.output;
}

TEST_F(RiseCommand, ManualSaysWhereTheBookIsOrHowToBuildIt) {
  const CommandResult result = runRise("manual --print-path");
  if (result.status == 0)
    EXPECT_NE(result.output.find("index.html"), std::string::npos) << result.output;
  else
    EXPECT_NE(result.output.find("--target manual"), std::string::npos) << result.output;
  EXPECT_EQ(runRise("manual --language fr").status, 2);
}

}  // namespace rise
