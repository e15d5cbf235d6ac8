#include "reports/step_player.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/image_io.hpp"
#include "render/buffer_images.hpp"
#include "reports/step_json.hpp"
#include "reports/step_player_html.hpp"
#include "reports/step_replay.hpp"

namespace rise {
namespace {

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
  file.close();
  if (!file)
    throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
}

// JSON inside a script element: "</" would end the element.
std::string forScript(std::string json) {
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3))
    json.replace(at, 2, "<\\/");
  return json;
}

std::string replaced(std::string text, const std::string& marker, const std::string& with) {
  text.replace(text.find(marker), marker.size(), with);
  return text;
}

std::string frameName(const char* folder, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%s/%04zu.png", folder, index + 1);
  return name;
}

// The every-how-many the budget kept, as the page reports it.
int keptEvery(const StepRecorder& recorder, std::size_t recorded, std::size_t kept) {
  if (recorder.budget().every > 0) return recorder.budget().every;
  return kept == 0 ? 1 : static_cast<int>(std::ceil(static_cast<double>(recorded) / kept));
}

}  // namespace

void writeStepPlayer(const std::filesystem::path& directory, const StepPlayerInput& input) {
  std::filesystem::create_directories(directory / "frames");
  const RenderResult& result = input.result;
  writeImage(result.image, directory / "image.png");
  std::vector<std::string> buffers;
  for (const auto& [name, raw] : result.buffers) {
    buffers.push_back(name + ".png");
    writeImage(visualizeBuffer(name, raw), directory / buffers.back(), Encoding::Linear);
  }

  const std::vector<Step> steps = input.recorder.keptSteps();
  StepReplay replay(input.scene.image.background, result.image);
  std::vector<std::string> stepTexts;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    replay.apply(steps[i]);
    const std::string frame = frameName("frames", i);
    writeImage(replay.image(), directory / frame);
    std::string depthFrame;
    if (replay.hasDepths()) {
      depthFrame = frameName("depth", i);
      std::filesystem::create_directories(directory / "depth");
      writeImage(replay.depthImage(), directory / depthFrame, Encoding::Linear);
    }
    stepTexts.push_back(stepJson(steps[i], static_cast<int>(i), frame, depthFrame));
  }

  const std::size_t recorded = input.recorder.allSteps().size();
  const StepsHeader header{input.scene.source,
                           std::string(input.algorithm.name),
                           result.image.width(),
                           result.image.height(),
                           keptEvery(input.recorder, recorded, steps.size()),
                           input.recorder.budget().region,
                           recorded,
                           input.recorder.stepsNotDetailed(),
                           &result.stats,
                           buffers};
  const std::string json = stepsJson(header, stepTexts);
  writeText(directory / "steps.json", json);
  const nlohmann::ordered_json about = {{"algorithm", input.algorithm.name},
                                        {"summary", input.algorithm.summary},
                                        {"citation", input.algorithm.citation}};
  std::string page = kStepPlayerHtml;
  page = replaced(page, "%%TITLE%%", std::string(input.algorithm.name) + " step by step");
  page = replaced(page, "%%STEPS%%", forScript(json));
  page = replaced(page, "%%ABOUT%%", forScript(about.dump()));
  writeText(directory / "index.html", page);
}

}  // namespace rise
