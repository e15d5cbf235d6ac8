// Rendering an animation: `--frames A-B` renders frames A to B of a scene
// that has an `animation` block, each into the file the output pattern names
// (run_%04d.png); `--array-index I --array-size N` takes every Nth frame of
// the range from the Ith, so that a job array's tasks share nothing; `--video`
// joins the frames into a film: an animated PNG, or a video made by ffmpeg.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "job.hpp"

namespace rise::cli {

struct AnimationOptions {
  std::vector<int> range;  // first, last; empty: a still image
  int arrayIndex = 0;
  int arraySize = 1;
  std::filesystem::path video;

  bool requested() const { return !range.empty(); }
};

void addAnimationOptions(CLI::App& command, AnimationOptions& options);

// The frames this process renders, or a message saying why the scene or the
// options do not allow them.
std::variant<std::vector<int>, std::string> framesToRender(const AnimationOptions& options,
                                                           const Scene& scene);

// The pattern's %d (or %04d and the like) replaced by the frame number.
std::filesystem::path framePath(const std::filesystem::path& pattern, int frame);

// The default pattern: the scene's name, the frame number, .png.
std::filesystem::path defaultFramePattern(const std::string& scenePath);

// Checks that the pattern has a frame number and that the film asked for, if
// any, can be made of its frames; the message otherwise.
std::optional<std::string> animationOutputProblem(const std::filesystem::path& pattern,
                                                  const std::filesystem::path& video);

// Writes one frame's result to its file; returns an exit status.
using FrameWriter = std::function<int(const RenderResult&, const std::filesystem::path&)>;

// Renders the frames the options choose, writing each as it is done, then
// the video if one is asked for. Returns the exit status.
int renderFrames(const Renderer& renderer, Job& job, const AnimationOptions& options,
                 const std::filesystem::path& pattern, const FrameWriter& write);

// Joins the frames into the film: an animated PNG when its name ends in .png
// or .apng, otherwise a video made by ffmpeg or, where ffmpeg is not
// installed, an animated PNG beside it (its name ending in .apng). Returns an
// exit status, having said what went wrong.
int writeVideo(const std::filesystem::path& pattern, const std::vector<int>& frames,
               const std::filesystem::path& video);

}  // namespace rise::cli
