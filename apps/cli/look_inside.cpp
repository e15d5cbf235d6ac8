#include "look_inside.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>

#include "algorithms/registry.hpp"
#include "core/text.hpp"
#include "job.hpp"
#include "option_checks.hpp"
#include "reports/ray_tree_picture.hpp"
#include "reports/ray_tree_text.hpp"
#include "reports/step_json.hpp"
#include "reports/step_player.hpp"

namespace rise::cli {
namespace {

// The algorithms that record a pixel's tree of rays.
std::vector<std::string_view> treeAlgorithmNames() {
  std::vector<std::string_view> names;
  for (const Renderer* renderer : renderersOffering(Look::RayTrees))
    names.push_back(renderer->name());
  return names;
}

struct ExplainOptions {
  SettingsOptions settings;
  std::string algorithm{defaultRenderer(Use::Explain).name()};
  std::filesystem::path directory;
  std::vector<int> region;  // x, y, width, height; empty: the whole image
  int every = 0;
  bool framesWithShapes = false;
};

struct InspectOptions {
  SettingsOptions settings;
  std::string algorithm{defaultRenderer(Use::Inspect).name()};
  std::vector<int> pixel;  // x, y
  std::filesystem::path json;
  std::filesystem::path picture;
};

// The region within the image, or a message.
std::optional<PixelRect> regionOf(const std::vector<int>& values, const RenderSettings& settings) {
  if (values.empty()) return std::nullopt;
  const PixelRect region{values[0], values[1], values[0] + values[2], values[1] + values[3]};
  const PixelRect image{0, 0, settings.width, settings.height};
  if (values[2] <= 0 || values[3] <= 0 || region.intersection(image).isEmpty())
    throw SettingsError("--region " + std::to_string(values[0]) + "," + std::to_string(values[1]) +
                        "," + std::to_string(values[2]) + "," + std::to_string(values[3]) +
                        ": expected a rectangle X,Y,W,H with W and H positive that overlaps the " +
                        std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " image");
  return region;
}

int explain(const ExplainOptions& options) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  if (!drawsShadowsAsked(renderer.description(), options.settings.request.settings.shadows))
    return kExitBadInput;
  const std::filesystem::path directory =
      options.directory.empty() ? defaultOutput(options.settings.scenePath, "") : options.directory;
  if (!outputsAreWritable({{directory / "index.html", "-o " + directory.string()}},
                          options.settings.scenePath, true))
    return kExitBadInput;
  std::variant<Job, int> prepared = prepare(options.settings, renderer);
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  const Job& job = std::get<Job>(prepared);
  StepBudget budget;
  budget.every = options.every;
  try {
    budget.region = regionOf(options.region, job.settings);
  } catch (const SettingsError& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitBadInput;
  }
  StepRecorder recorder(budget);
  const std::optional<RenderResult> rendered = renderWithProgress(renderer, job, &recorder);
  if (!rendered) return kExitBadInput;
  const RenderResult& result = *rendered;
  try {
    writeStepPlayer(
        directory, {job.scene, renderer.description(), result, recorder, options.framesWithShapes});
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << renderer.name() << ": " << counted(recorder.allSteps().size(), "step")
            << " recorded\n"
            << "wrote " << (directory / "index.html").string() << "\n";
  return 0;
}

int inspect(const InspectOptions& options) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  if (!renderer.description().offers(Look::RayTrees)) {
    std::cerr << "rise: -a " << options.algorithm
              << ": traces no rays from the eye, and so has no ray tree; "
              << "expected one of " << joined(treeAlgorithmNames())
              << " (`rise explain` shows the steps of the others)\n";
    return kExitBadInput;
  }
  if (!options.picture.empty() && options.picture.extension() != ".svg") {
    std::cerr << "rise: --picture " << options.picture.string()
              << ": expected a file name ending in .svg\n";
    return kExitBadInput;
  }
  std::vector<PlannedOutput> outputs;
  if (!options.json.empty()) outputs.push_back({options.json, "-o"});
  if (!options.picture.empty()) outputs.push_back({options.picture, "--picture"});
  if (!outputsAreWritable(outputs, options.settings.scenePath)) return kExitBadInput;
  std::variant<Job, int> prepared = prepare(options.settings, renderer);
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  Job& job = std::get<Job>(prepared);
  const glm::ivec2 pixel(options.pixel[0], options.pixel[1]);
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= job.settings.width ||
      pixel.y >= job.settings.height) {
    std::cerr << "rise: --pixel " << pixel.x << "," << pixel.y << ": expected a pixel of the "
              << job.settings.width << "x" << job.settings.height << " image, from 0,0 to "
              << job.settings.width - 1 << "," << job.settings.height - 1 << "\n";
    return kExitBadInput;
  }
  StepBudget budget;
  budget.treePixel = pixel;
  StepRecorder recorder(budget);
  const std::optional<RenderResult> rendered = renderWithProgress(renderer, job, &recorder);
  if (!rendered) return kExitBadInput;
  const RenderResult& result = *rendered;
  const std::vector<RayTree> trees = recorder.trees();
  const Color color = result.image.at(pixel.x, pixel.y);
  if (trees.empty()) {
    std::cerr << "rise: " << renderer.name() << " recorded no ray tree for pixel " << pixel.x << ","
              << pixel.y << " (the adaptive pattern traces no fixed samples: choose "
              << "another --pattern)\n";
    return kExitBadInput;
  }
  printRayTrees(std::cout, job.scene, trees, color);
  try {
    if (!options.json.empty()) {
      std::ofstream file(options.json);
      file << rayTreesJson(job.scene, renderer.name(), trees, color) << "\n";
      file.close();
      if (!file) throw std::runtime_error(options.json.string() + ": cannot write");
    }
    if (!options.picture.empty())
      writeRayTreePicture(options.picture, job.scene, job.settings, result.image, trees);
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  return 0;
}

}  // namespace

std::function<std::optional<int>()> addLookInsideCommands(CLI::App& app) {
  auto explainOptions = std::make_shared<ExplainOptions>();
  CLI::App* explainCommand = app.add_subcommand(
      "explain",
      "Record an algorithm's steps and write a page that plays them: the image after each "
      "step, what the step did, the counts so far");
  addSettingsOptions(*explainCommand, explainOptions->settings);
  explainCommand
      ->add_option("-a,--algorithm", explainOptions->algorithm, "Algorithm (see `rise algorithms`)")
      ->capture_default_str()
      ->check(CLI::IsMember(algorithmNames()));
  explainCommand->add_option("-o,--output", explainOptions->directory,
                             "Folder to write the page into (default: the scene's name)");
  explainCommand
      ->add_option("--region", explainOptions->region,
                   "Keep only the steps that touch this rectangle of pixels: X,Y,W,H")
      ->delimiter(',')
      ->expected(4);
  explainCommand
      ->add_option("--every", explainOptions->every,
                   "Show every Nth step (default: as many as keep about 200)")
      ->check(wholeNumberFrom(1));
  explainCommand->add_flag(
      "--shapes", explainOptions->framesWithShapes,
      "Also write shapes/NNNN.png: each frame with the step's shapes (windows, "
      "spans, edges) drawn on it, for slides and figures");

  auto inspectOptions = std::make_shared<InspectOptions>();
  CLI::App* inspectCommand = app.add_subcommand(
      "inspect", "Print the tree of rays behind one pixel, and write it as JSON and a picture");
  addSettingsOptions(*inspectCommand, inspectOptions->settings);
  inspectCommand->add_option("--pixel", inspectOptions->pixel, "The pixel: X,Y from the top left")
      ->option_text("X,Y")
      ->delimiter(',')
      ->expected(2)
      ->required();
  inspectCommand
      ->add_option("-a,--algorithm", inspectOptions->algorithm, "Algorithm, one that traces rays")
      ->capture_default_str()
      // Any algorithm's name is taken, so that one without rays is told why.
      ->check(CLI::Validator(
          [](const std::string& name) -> std::string {
            const std::vector<std::string> all = algorithmNames();
            if (std::find(all.begin(), all.end(), name) != all.end()) return {};
            return name + "; expected one of: " + joined(treeAlgorithmNames());
          },
          "{" + joined(treeAlgorithmNames()) + "}"));
  inspectCommand->add_option("-o,--output", inspectOptions->json, "Also write the tree as JSON");
  inspectCommand->add_option(
      "--picture", inspectOptions->picture,
      "Also draw the rays over the scene, from the camera and from beside them (.svg)");

  return [=]() -> std::optional<int> {
    if (*explainCommand) return explain(*explainOptions);
    if (*inspectCommand) return inspect(*inspectOptions);
    return std::nullopt;
  };
}

}  // namespace rise::cli
