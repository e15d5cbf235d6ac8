#include "animation.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <regex>

#include "core/text.hpp"
#include "io/animated_png.hpp"
#include "io/atomic_file.hpp"
#include "io/image_io.hpp"
#include "option_checks.hpp"
#include "output_check.hpp"

namespace rise::cli {
namespace {

namespace fs = std::filesystem;

// The printf-style frame number of a pattern: %d, or %04d and its kin.
const std::regex kFrameNumber("%(0?[1-9]?)d");

// "3-17": the first and the last frame.
std::string parseRange(const std::string& text, std::vector<int>& range) {
  static const std::regex kRange(R"((\d{1,6})(?:-(\d{1,6}))?)");
  std::smatch match;
  if (!std::regex_match(text, match, kRange))
    return "--frames " + text + ": expected FIRST-LAST, as 0-39, or one frame";
  const int first = std::stoi(match[1]);
  const int last = match[2].matched ? std::stoi(match[2]) : first;
  if (last < first) return "--frames " + text + ": the last frame comes before the first";
  range = {first, last};
  return "";
}

// A film's frames a second.
constexpr int kFramesPerSecond = 24;

bool isAnimatedPng(const fs::path& video) {
  const std::string extension = lowercaseExtension(video);
  return extension == ".png" || extension == ".apng";
}

bool ffmpegIsInstalled() { return std::system("command -v ffmpeg > /dev/null 2>&1") == 0; }

std::string shellQuoted(const std::string& text) {
  std::string result = "'";
  for (char c : text) result += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return result + "'";
}

}  // namespace

void addAnimationOptions(CLI::App& command, AnimationOptions& options) {
  command
      .add_option_function<std::string>(
          "--frames",
          [&options](const std::string& text) {
            if (std::string problem = parseRange(text, options.range); !problem.empty())
              throw CLI::ValidationError(problem);
          },
          "Render frames FIRST-LAST of the scene's animation, into -o's pattern (run_%04d.png)")
      ->type_name("FIRST-LAST");
  command
      .add_option("--array-index", options.arrayIndex,
                  "With --frames: this task's number in a job array, from 0")
      ->check(wholeNumberFrom(0));
  command
      .add_option("--array-size", options.arraySize,
                  "With --frames: the tasks of the job array; each renders every Nth frame")
      ->check(wholeNumberFrom(1));
  command.add_option("--video", options.video,
                     "With --frames: join the frames into this film: an animated PNG (.png, "
                     ".apng), or a video (.mp4) made by ffmpeg, or an animated PNG without it");
}

std::variant<std::vector<int>, std::string> framesToRender(const AnimationOptions& options,
                                                           const Scene& scene) {
  if (scene.animationFrames == 0)
    return scene.source + ": --frames needs an animation; expected 'animation: {frames: N}'";
  if (options.range[1] >= scene.animationFrames)
    return "--frames " + std::to_string(options.range[0]) + "-" + std::to_string(options.range[1]) +
           ": " + scene.source + "'s animation has frames 0 to " +
           std::to_string(scene.animationFrames - 1);
  if (options.arrayIndex >= options.arraySize)
    return "--array-index " + std::to_string(options.arrayIndex) +
           ": expected a number below --array-size " + std::to_string(options.arraySize);
  if (!options.video.empty() && options.arraySize > 1)
    return "--video joins the whole range; with --array-size, join the frames once every task "
           "is done";
  std::vector<int> frames;
  for (int frame = options.range[0] + options.arrayIndex; frame <= options.range[1];
       frame += options.arraySize)
    frames.push_back(frame);
  return frames;
}

fs::path framePath(const fs::path& pattern, int frame) {
  const std::string name = pattern.filename().string();
  std::smatch match;
  std::regex_search(name, match, kFrameNumber);
  const std::string format = "%" + match[1].str() + "d";
  char number[32];
  std::snprintf(number, sizeof number, format.c_str(), frame);
  return pattern.parent_path() / (match.prefix().str() + number + match.suffix().str());
}

fs::path defaultFramePattern(const std::string& scenePath) {
  const std::string name = scenePath == "-" ? "render" : fs::path(scenePath).stem().string();
  return name + "_%04d.png";
}

std::optional<std::string> animationOutputProblem(const fs::path& pattern, const fs::path& video) {
  if (!std::regex_search(pattern.filename().string(), kFrameNumber))
    return "-o " + pattern.string() +
           ": expected a frame number in the name, as run_%04d.png, for --frames";
  if (!video.empty() && lowercaseExtension(pattern) != ".png" &&
      (isAnimatedPng(video) || !ffmpegIsInstalled()))
    return "--video " + video.string() + ": an animated PNG is made of PNG frames, not of " +
           pattern.filename().string();
  if (!video.empty()) {
    if (std::string problem = outputsProblem({{video, "--video"}}, "-"); !problem.empty())
      return problem;
  }
  return std::nullopt;
}

int renderFrames(const Renderer& renderer, Job& job, const AnimationOptions& options,
                 const fs::path& pattern, const FrameWriter& write) {
  const auto chosen = framesToRender(options, job.scene);
  if (const std::string* problem = std::get_if<std::string>(&chosen)) {
    std::cerr << "rise: " << *problem << "\n";
    return kExitBadInput;
  }
  if (const std::optional<std::string> problem = animationOutputProblem(pattern, options.video)) {
    std::cerr << "rise: " << *problem << "\n";
    return kExitBadInput;
  }
  const std::vector<int>& frames = std::get<std::vector<int>>(chosen);
  const Camera camera = job.scene.camera;
  for (int frame : frames) {
    job.scene.camera = cameraForFrame(camera, frame, job.scene.animationFrames);
    const std::optional<RenderResult> rendered = renderWithProgress(renderer, job);
    if (!rendered) return kExitBadInput;
    if (const int status = write(*rendered, framePath(pattern, frame))) return status;
  }
  if (options.video.empty()) return 0;
  return writeVideo(pattern, frames, options.video);
}

namespace {

int writeAnimatedPngOf(const std::vector<fs::path>& frames, const fs::path& film) {
  try {
    writeAnimatedPng(frames, film, kFramesPerSecond);
  } catch (const ImageFileError& error) {
    std::cerr << "rise: --video " << film.string() << ": " << error.what() << "\n";
    return kExitOutputError;
  } catch (const OutputFileError& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << "wrote " << film.string() << "\n";
  return 0;
}

// ffmpeg reads the frames through the pattern, from the first; it writes
// beside the video and renames, so that no half-written film is left.
int writeVideoWithFfmpeg(const fs::path& pattern, const std::vector<int>& frames,
                         const fs::path& video) {
  const fs::path partial = video.parent_path() / (".part." + video.filename().string());
  const std::string command =
      "ffmpeg -loglevel error -y -framerate " + std::to_string(kFramesPerSecond) +
      " -start_number " + std::to_string(frames.front()) + " -i " + shellQuoted(pattern.string()) +
      " -frames:v " + std::to_string(frames.size()) + " -pix_fmt yuv420p " +
      shellQuoted(partial.string());
  if (std::system(command.c_str()) != 0) {
    fs::remove(partial);
    std::cerr << "rise: --video " << video.string() << ": ffmpeg failed\n";
    return kExitOutputError;
  }
  fs::rename(partial, video);
  std::cerr << "wrote " << video.string() << "\n";
  return 0;
}

}  // namespace

int writeVideo(const fs::path& pattern, const std::vector<int>& frames, const fs::path& video) {
  std::vector<fs::path> framePaths;
  for (int frame : frames) framePaths.push_back(framePath(pattern, frame));
  if (isAnimatedPng(video)) return writeAnimatedPngOf(framePaths, video);
  if (ffmpegIsInstalled()) return writeVideoWithFfmpeg(pattern, frames, video);
  const fs::path film = fs::path(video).replace_extension(".apng");
  std::cerr << "rise: --video " << video.string()
            << ": ffmpeg is not installed (Debian: apt install ffmpeg); the frames are joined into "
               "an animated PNG, "
            << film.string() << ", instead\n";
  return writeAnimatedPngOf(framePaths, film);
}

}  // namespace rise::cli
