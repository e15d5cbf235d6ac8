// Rendering an animation: `rise render --frames`, split among the tasks of a
// job array, and joined into a film.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/animated_png.hpp"
#include "io/image_io.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

class AnimationCommand : public RiseCommand {
 protected:
  CommandResult renderFrames(const std::string& options) {
    return runRise("render " + example("animation.yaml") + " --width 40 --height 30 --threads 2 " +
                   options);
  }
  Image frame(const std::string& name) { return readImage(file(name), Encoding::Linear); }
  static std::vector<std::uint8_t> bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

TEST_F(AnimationCommand, AJobArrayRendersTheFramesOfOneRun) {
  const CommandResult whole = renderFrames("--frames 2-5 -o " + file("whole_%03d.png").string());
  ASSERT_EQ(whole.status, 0) << whole.output;
  for (int task = 0; task < 2; ++task) {
    const CommandResult part =
        renderFrames("--frames 2-5 --array-size 2 --array-index " + std::to_string(task) + " -o " +
                     file("task" + std::to_string(task) + "_%d.png").string());
    ASSERT_EQ(part.status, 0) << part.output;
  }
  EXPECT_FALSE(fs::exists(file("whole_001.png")));
  EXPECT_FALSE(fs::exists(file("whole_006.png")));
  EXPECT_EQ(frame("task0_2.png").pixels(), frame("whole_002.png").pixels());
  EXPECT_EQ(frame("task1_3.png").pixels(), frame("whole_003.png").pixels());
  EXPECT_EQ(frame("task0_4.png").pixels(), frame("whole_004.png").pixels());
  EXPECT_EQ(frame("task1_5.png").pixels(), frame("whole_005.png").pixels());
  EXPECT_FALSE(fs::exists(file("task0_3.png")));
  EXPECT_NE(frame("whole_002.png").pixels(), frame("whole_003.png").pixels());
}

TEST_F(AnimationCommand, AStillSceneHasNoFrames) {
  const CommandResult result = runRise("render " + example("classic.yaml") +
                                       " --width 40 --frames 0-3 -o " + file("f_%d.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("expected 'animation: {frames: N}'"), std::string::npos)
      << result.output;
}

TEST_F(AnimationCommand, FramesBeyondTheAnimationAreBadInput) {
  const CommandResult result = renderFrames("--frames 20-24 -o " + file("f_%d.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("has frames 0 to 23"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(file("f_20.png")));
}

TEST_F(AnimationCommand, TheOutputNeedsAFrameNumber) {
  const CommandResult result = renderFrames("--frames 0-1 -o " + file("film.png").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("expected a frame number"), std::string::npos) << result.output;
}

TEST_F(AnimationCommand, AVideoJoinsTheFramesWithFfmpegOrIntoAnAnimatedPng) {
  const CommandResult result = renderFrames("--frames 0-2 -o " + file("f_%02d.png").string() +
                                            " --video " + file("film.mp4").string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(fs::exists(file("f_02.png")));
  if (runCommand("command -v ffmpeg").status != 0) {
    EXPECT_NE(result.output.find("ffmpeg is not installed"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(file("film.mp4")));
    EXPECT_EQ(frame("film.apng").pixels(), frame("f_00.png").pixels());
    return;
  }
  EXPECT_GT(fs::file_size(file("film.mp4")), 0u);
}

TEST_F(AnimationCommand, AnAnimatedPngHoldsEveryFrame) {
  const CommandResult result = renderFrames("--frames 3-5 -o " + file("f_%d.png").string() +
                                            " --video " + file("film.png").string());
  ASSERT_EQ(result.status, 0) << result.output;
  const std::vector<PngChunk> chunks = pngChunks(bytesOf(file("film.png")), file("film.png"));
  EXPECT_EQ(std::count_if(chunks.begin(), chunks.end(),
                          [](const PngChunk& chunk) { return chunk.type == "fcTL"; }),
            3);
  // A viewer without animation shows the first frame.
  EXPECT_EQ(frame("film.png").pixels(), frame("f_3.png").pixels());
}

TEST_F(AnimationCommand, AnAnimatedPngOfOpenExrFramesIsRefusedBeforeRendering) {
  const CommandResult result = renderFrames("--frames 0-1 -o " + file("f_%d.exr").string() +
                                            " --video " + file("film.apng").string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("an animated PNG is made of PNG frames"), std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(file("f_0.exr")));
}

}  // namespace
}  // namespace rise
