// Bad input of the kinds a probe with files from the internet and typos
// found, each refused with one clear message before any work, or read as it
// was meant: names too long or holding control characters, directions too
// long to normalise, aliases that repeat a large node, scenes of 100,000
// materials, models whose side files are pipes or whose formats RISE does
// not read, loops of links, and command-line values out of range.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/scene_file.hpp"
#include "scene/light.hpp"
#include "support/image_agreement_testing.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCameraAndLight =
    "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
    "lights: [{point: {position: [0, 5, -5]}}]\n";

std::string loadError(const std::string& text) {
  try {
    loadScene(text, "s.yaml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

class BadInput : public RiseCommand {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name), std::ios::binary) << text;
    return file(name);
  }
  std::string loadFileError(const fs::path& path) const {
    try {
      loadSceneFile(path);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "no error";
  }
};

TEST(BadInputNames, ANameOfMillionsOfLettersIsShownShortenedAndNotMeasured) {
  const std::string name(4'000'000, 'b');
  const std::string error =
      loadError(std::string(kCameraAndLight) + "materials: {a: {color: [1, 1, 1]}}\n" +
                "objects: [{sphere: {center: [0, 0, 0], radius: 1, material: " + name + "}}]\n");
  EXPECT_LT(error.size(), 200u) << error.substr(0, 300);
  EXPECT_NE(error.find("'bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb...' (4000000 characters)"),
            std::string::npos)
      << error.substr(0, 300);
}

TEST(BadInputNames, AControlCharacterInANameIsShownByItsCode) {
  const std::string error =
      loadError(std::string(kCameraAndLight) +
                "materials: {\"a\\0b\": {color: [1, 1, 1], kx: 1}}\n" + "objects: []\n");
  EXPECT_EQ(error, "s.yaml:3:40: unknown key 'kx' in material 'a\\x00b'; did you mean 'ka'?");
}

TEST(BadInputValues, ADirectionOfAnyFiniteLengthIsNormalised) {
  for (const std::string direction : {"[1e20, -1e20, 0]", "[1e-30, -1e-30, 0]", "[3, -3, 0]"}) {
    const Scene scene =
        loadScene("camera: {position: [0, 0, -5], look_at: [0, 0, 0], up: " + direction + "}\n" +
                      "lights: [{directional: {direction: " + direction + "}}]\n" +
                      "objects: [{plane: {point: [0, 0, 0], normal: " + direction +
                      ", material: m}}]\n" + "materials: {m: {color: [1, 1, 1]}}\n",
                  "s.yaml");
    EXPECT_NEAR(glm::length(scene.camera.up), 1.0f, 1e-6f) << direction;
    const auto& light = dynamic_cast<const DirectionalLight&>(*scene.lights.front());
    EXPECT_NEAR(light.direction().x, 1.0f / std::sqrt(2.0f), 1e-6f) << direction;
  }
  EXPECT_EQ(loadError(std::string(kCameraAndLight) +
                      "objects: [{plane: {point: [0, 0, 0], normal: [0, 0, 0], material: m}}]\n" +
                      "materials: {m: {color: [1, 1, 1]}}\n"),
            "s.yaml:3:46: 'normal' in plane is [0, 0, 0]; expected a direction, not the zero "
            "vector");
}

// Ten aliases of ten aliases of ... a list: a few lines that stand for
// billions of values, each read again by the scene's reader.
TEST(BadInputYaml, AliasesThatRepeatALargeNodeAreRefusedAtOnce) {
  std::string text = std::string(kCameraAndLight) + "a0: &a0 [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string name = std::to_string(level), previous = std::to_string(level - 1);
    text.append("a").append(name).append(": &a").append(name).append(" [");
    for (int i = 0; i < 10; ++i) text.append(i ? ", *a" : "*a").append(previous);
    text += "]\n";
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string error = loadError(text + "objects: []\n");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  EXPECT_NE(error.find("repeats"), std::string::npos) << error;
  EXPECT_NE(error.find("values, making more than 1000000 in the scene"), std::string::npos)
      << error;
}

// Loading time linear in the file: ten times the objects and materials take
// about ten times as long, not a hundred.
TEST(BadInputScale, AScaleOfManyMaterialsAndObjectsLoadsInLinearTime) {
  const auto secondsToLoad = [](int count) {
    std::string text = std::string(kCameraAndLight) + "materials:\n";
    for (int i = 0; i < count; ++i) text += "  m" + std::to_string(i) + ": {color: [1, 1, 1]}\n";
    text += "objects:\n";
    for (int i = 0; i < count; ++i)
      text += "  - sphere: {center: [" + std::to_string(i) + ", 0, 0], radius: 0.4, material: m" +
              std::to_string(count - 1 - i) + "}\n";
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = loadScene(text, "s.yaml");
    EXPECT_EQ(scene.shapes.size(), static_cast<std::size_t>(count));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
#ifdef RISE_SANITIZED_BUILD
  constexpr int kFew = 1'000;
#else
  constexpr int kFew = 5'000;
#endif
  const double few = secondsToLoad(kFew);
  const double many = secondsToLoad(10 * kFew);
  EXPECT_LT(many, 30.0 * few + 0.05) << few << " s for " << kFew << ", " << many << " s for ten "
                                     << "times as many";
}

TEST_F(BadInput, AModelsSideFileThatIsAPipeIsRefusedByName) {
  write("m.obj", "mtllib side.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_EQ(mkfifo(file("side.mtl").c_str(), 0600), 0);
  const fs::path scene =
      write("s.yaml", std::string(kCameraAndLight) + "materials: {a: {color: [1, 1, 1]}}\n" +
                          "objects: [{mesh: {file: m.obj, material: a}}]\n");
  EXPECT_EQ(loadFileError(scene),
            scene.string() +
                ":4:25: cannot load mesh 'm.obj': cannot read a file it names: side.mtl: not a "
                "regular file (a device or a pipe); expected a file on disk");
}

TEST_F(BadInput, AModelFormatTheManualDoesNotListIsRefusedByName) {
  for (const std::string name : {"m.md5mesh", "m.ase", "m.smd", "m.ogex", "m.fbx"}) {
    write(name, "corrupt");
    const fs::path scene =
        write("s.yaml", std::string(kCameraAndLight) + "materials: {a: {color: [1, 1, 1]}}\n" +
                            "objects: [{mesh: {file: " + name + ", material: a}}]\n");
    const std::string error = loadFileError(scene);
    EXPECT_NE(error.find("is not a model format that RISE reads; expected .obj, .ply"),
              std::string::npos)
        << error;
  }
}

TEST_F(BadInput, ALoopOfLinksIsNamedAsOne) {
  fs::create_symlink(file("b.yaml"), file("a.yaml"));
  fs::create_symlink(file("a.yaml"), file("b.yaml"));
  EXPECT_EQ(loadFileError(file("a.yaml")),
            file("a.yaml").string() +
                ": cannot open the file: its symbolic links lead round in a "
                "loop");
  const CommandResult result = runRise("validate " + file("a.yaml").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.output.find("filesystem"), std::string::npos) << result.output;
}

TEST_F(BadInput, OneImageNamedByManyMaterialsIsReadOnce) {
  fs::copy_file(std::string(RISE_SOURCE_DIR) + "/examples/textures/earth.jpg", file("earth.jpg"));
  std::string text = std::string(kCameraAndLight) + "materials:\n";
  for (int i = 0; i < 12; ++i)
    text += "  m" + std::to_string(i) + ": {texture: {image: earth.jpg}}\n";
  text += "objects:\n";
  for (int i = 0; i < 12; ++i)
    text += "  - sphere: {center: [0, 0, 0], radius: 1, material: m" + std::to_string(i) + "}\n";
  const Scene scene = loadSceneFile(write("s.yaml", text));
  for (const Material& material : scene.materials)
    EXPECT_EQ(material.texture, scene.materials.front().texture) << material.name;
}

TEST_F(BadInput, ACommandLineValueOutOfRangeIsToldInTheUsersWords) {
  const CommandResult every =
      runRise("explain " + example("classic.yaml") + " --every 0 -o " + file("out").string());
  EXPECT_EQ(every.status, 2);
  EXPECT_NE(every.output.find("--every: 0; expected a whole number >= 1"), std::string::npos)
      << every.output;
  const CommandResult encoding = runRise("render " + example("classic.yaml") +
                                         " --encoding gamma -o " + file("x.png").string());
  EXPECT_EQ(encoding.status, 2);
  EXPECT_NE(encoding.output.find("--encoding: gamma; expected one of linear, srgb"),
            std::string::npos)
      << encoding.output;
  const CommandResult folder =
      runRise("render - -o " + file("x.png").string() + " < " + directory_.string());
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.output.find("<stdin>: standard input is a folder"), std::string::npos)
      << folder.output;
  EXPECT_FALSE(fs::exists(file("x.png")));
}

TEST_F(BadInput, OutputsThatTheFileSystemRefusesOrThatAreNotFilesAreToldApart) {
  const std::string scene = example("classic.yaml") + " --width 32 --height 24";
  const CommandResult tooLong =
      runRise("render " + scene + " -o " + std::string(300, 'x') + ".png");
  EXPECT_EQ(tooLong.status, 2);
  EXPECT_NE(tooLong.output.find("cannot be written (File name too long)"), std::string::npos)
      << tooLong.output;
  const CommandResult full =
      runRise("render " + scene + " -o " + file("a.png").string() + " --stats /dev/full");
  EXPECT_EQ(full.status, 1);
  EXPECT_NE(full.output.find("/dev/full: cannot write (No space left on device)"),
            std::string::npos)
      << full.output;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
  const CommandResult standardOutput =
      runRise("render " + scene + " -o " + file("a.png").string() + " --stats -");
  EXPECT_EQ(standardOutput.status, 0);
  EXPECT_NE(standardOutput.output.find("\"algorithm\": \"ray-tracing\""), std::string::npos)
      << standardOutput.output;
  EXPECT_FALSE(fs::exists("-"));
}

// What merge and --video will write is checked before any work, as render
// checks its outputs: a wrong format or a missing folder is bad input.
TEST_F(BadInput, MergeAndVideoOutputsAreCheckedBeforeTheWork) {
  const std::string scene = example("classic.yaml") + " --width 32 --height 24";
  ASSERT_EQ(runRise("render " + scene + " --tile 0,0,32,24 -o " + file("a.png").string()).status,
            0);
  for (const std::string output : {"whole.gif", "missing/whole.png"}) {
    const CommandResult merged =
        runRise("merge " + directory_.string() + " -o " + file(output).string());
    EXPECT_EQ(merged.status, 2) << merged.output;
  }
  const CommandResult video = runRise(
      "render " + example("animation.yaml") + " --width 16 --height 12 --frames 0-1 " + "--video " +
      file("missing/film.png").string() + " -o " + file("f_%04d.png").string());
  EXPECT_EQ(video.status, 2);
  EXPECT_NE(video.output.find("does not exist"), std::string::npos) << video.output;
  EXPECT_FALSE(fs::exists(file("f_0000.png")));
}

TEST_F(BadInput, ATileReachingPastTheImageIsToldSo) {
  const CommandResult result =
      runRise("render " + example("classic.yaml") +
              " --width 32 --height 24 --tile 30,20,16,24 -o " + file("t.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("X + W <= 32, Y + H <= 24"), std::string::npos) << result.output;
  const CommandResult huge = runRise("render " + example("classic.yaml") +
                                     " --tile 2147483647,0,16,24 -o " + file("t.png").string());
  EXPECT_EQ(huge.status, 2);
  EXPECT_NE(huge.output.find("expected a whole number from 0 to 32768"), std::string::npos)
      << huge.output;
}

// Two outputs of one command that are one file, by a link or as a tile's
// place beside its image, are refused before the render, which writes none.
TEST_F(BadInput, TwoNamesOfOneFileAreRefusedBeforeTheRender) {
  const std::string scene = example("classic.yaml") + " --width 32 --height 24";
  write("a.png", "");
  fs::create_hard_link(file("a.png"), file("stats.json"));
  const CommandResult linked = runRise("render " + scene + " -o " + file("a.png").string() +
                                       " --stats " + file("stats.json").string());
  EXPECT_EQ(linked.status, 2);
  EXPECT_NE(
      linked.output.find("--stats " + file("stats.json").string() + ": is the file -o names too"),
      std::string::npos)
      << linked.output;
  EXPECT_EQ(fs::file_size(file("a.png")), 0u);
  const CommandResult place =
      runRise("render " + scene + " --tile 0,0,16,24 -o " + file("t.exr").string() + " --stats " +
              file("t.exr.tile.json").string());
  EXPECT_EQ(place.status, 2);
  EXPECT_NE(place.output.find("--tile's place " + file("t.exr.tile.json").string() +
                              ": is the file --stats names too"),
            std::string::npos)
      << place.output;
  EXPECT_FALSE(fs::exists(file("t.exr")));
}

// "frames: [5, 5]" moves from a keyframe to itself: the model stands in it,
// as with "frame: 5", for every algorithm (it crashed every one).
TEST_F(BadInput, AnMd2MovingFromAKeyframeToItselfStandsInIt) {
  const std::string model = std::string(RISE_SOURCE_DIR) + "/examples/models/sydney/sydney.md2";
  const auto sceneIn = [&](const std::string& posing) {
    return loadScene(
        "camera: {position: [0, 0, -120], look_at: [0, 0, 0], shutter: [0, 1]}\n"
        "lights: [{point: {position: [0, 50, -100]}}]\n"
        "materials: {m: {}}\nobjects: [{mesh: {file: " +
            model + ", material: m, " + posing + "}}]\n",
        "s.yaml");
  };
  const Scene still = sceneIn("frame: 5"), moving = sceneIn("frames: [5, 5]");
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.sampling.samples = 2;
  for (const std::string_view algorithm : {"ray-tracing", "z-buffer", "hybrid"}) {
    const Image expected = image_agreement_testing::renderWith(algorithm, still, settings).image;
    const Image drawn = image_agreement_testing::renderWith(algorithm, moving, settings).image;
    EXPECT_EQ(drawn.pixels(), expected.pixels()) << algorithm;
  }
}

}  // namespace
}  // namespace rise
