// `rise`: the command line of the Realistic Image Synthesis Environment. A thin
// layer over the library: it parses options, loads the scene, runs one
// Renderer and writes what it returned.
//
// Exit status: 0 done, 1 an output file could not be written, 2 bad input
// (a scene file error or a wrong option); on status 2 no image is written.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <iostream>
#include <iterator>
#include <sstream>

#include "core/image_io.hpp"
#include "progress_bar.hpp"
#include "render/buffer_images.hpp"
#include "render/registry.hpp"
#include "render/tiles.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_file.hpp"
#include "stats_report.hpp"

namespace rise::cli {
namespace {

constexpr int kExitOutputError = 1;
constexpr int kExitBadInput = 2;

struct RenderOptions {
  std::string scenePath;
  std::filesystem::path output;
  std::string algorithm = "ray-tracing";
  int width = 0;  // 0: as the scene says
  int height = 0;
  int threads = 0;
  int maxDepth = 5;
  std::filesystem::path statsPath;
  Encoding encoding = Encoding::Srgb;
  std::vector<std::string> buffers;
  Accel accel = Accel::Bvh;
  std::optional<int> samples;  // unset: as the scene says
  std::optional<SamplePattern> pattern;
  std::optional<FilterKind> filter;
  std::optional<float> adaptiveThreshold;
  std::uint64_t seed = 0;
  Shading shading = Shading::Phong;
  bool noCulling = false;
  int tessellation = 8;
  float planeSize = 1000.0f;
};

// The scene's pixel sampling with the command line's choices over it.
PixelSampling pixelSampling(const RenderOptions& options, const PixelSampling& scene) {
  PixelSampling sampling = chooseSampling(scene, options.samples, options.pattern);
  if (options.filter) sampling.filter = *options.filter;
  if (options.adaptiveThreshold) sampling.adaptiveThreshold = *options.adaptiveThreshold;
  return sampling;
}

std::map<std::string, Accel> accelNamesToValues() {
  std::map<std::string, Accel> names;
  for (Accel accel : kAllAccels) names.emplace(accelName(accel), accel);
  return names;
}

std::string availableAccelNames() {
  std::string names;
  for (Accel accel : availableAccels())
    names += (names.empty() ? "" : ", ") + std::string(accelName(accel));
  return names;
}

Scene loadScene(const std::string& path) {
  if (path != "-") return loadSceneFile(path);
  const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
  return rise::loadScene(text, "<stdin>");
}

// The image size: the scene's, unless the command line gives one; a single
// dimension keeps the scene's aspect ratio.
std::pair<int, int> imageSize(const RenderOptions& options, const ImageSpec& image) {
  const double aspect = static_cast<double>(image.width) / image.height;
  if (options.width > 0 && options.height > 0) return {options.width, options.height};
  if (options.width > 0)
    return {options.width, std::max(1, static_cast<int>(std::lround(options.width / aspect)))};
  if (options.height > 0)
    return {std::max(1, static_cast<int>(std::lround(options.height * aspect))), options.height};
  return {image.width, image.height};
}

std::filesystem::path defaultOutput(const std::string& scenePath) {
  if (scenePath == "-") return "render.png";
  return std::filesystem::path(scenePath).filename().replace_extension(".png");
}

// out.png -> out.depth.png: the auxiliary buffers are written beside the image.
std::filesystem::path bufferPath(const std::filesystem::path& output, const std::string& name) {
  std::filesystem::path path = output;
  return path.replace_extension("." + name + output.extension().string());
}

// EXR keeps the raw values; the 8-bit formats get a picture of them.
void writeBuffer(const RenderResult& result, const std::string& name,
                 const std::filesystem::path& output) {
  const Image& raw = result.buffers.find(name)->second;
  const std::filesystem::path path = bufferPath(output, name);
  if (output.extension() == ".exr")
    writeImage(raw, path, Encoding::Linear);
  else
    writeImage(visualizeBuffer(name, raw), path, Encoding::Linear);
}

int render(const RenderOptions& options) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  Scene scene;
  try {
    scene = loadScene(options.scenePath);
  } catch (const SceneError& error) {
    std::cerr << error.what() << "\n";
    return kExitBadInput;
  }

  RenderSettings settings;
  std::tie(settings.width, settings.height) = imageSize(options, scene.image);
  settings.threads = resolveThreadCount(options.threads);
  settings.maxDepth = options.maxDepth;
  settings.shading = options.shading;
  settings.backfaceCulling = !options.noCulling;
  settings.tessellation = options.tessellation;
  settings.planeSize = options.planeSize;
  if (!isAvailable(options.accel)) {
    std::cerr << "rise: --accel " << accelName(options.accel)
              << ": this build has no such structure (Embree was not found when it was built); "
              << "available: " << availableAccelNames() << "\n";
    return kExitBadInput;
  }
  settings.accel = options.accel;
  settings.sampling = pixelSampling(options, scene.image.sampling);
  settings.seed = options.seed;
  if (const std::string problem = samplingProblem(settings.sampling); !problem.empty()) {
    std::cerr << "rise: " << problem << "\n";
    return kExitBadInput;
  }

  RenderResult result;
  {
    ProgressBar progress(std::string(renderer.name()));
    result = renderTimed(renderer, scene, settings, progress);
  }
  for (const std::string& name : options.buffers) {
    if (!result.buffers.contains(name)) {
      std::cerr << "rise: " << renderer.name() << " has no '" << name << "' buffer\n";
      return kExitBadInput;
    }
  }

  const std::filesystem::path output =
      options.output.empty() ? defaultOutput(options.scenePath) : options.output;
  const RenderDescription description{scene.source, std::string(renderer.name()), settings.width,
                                      settings.height, settings.threads};
  try {
    writeImage(result.image, output, options.encoding);
    for (const std::string& name : options.buffers) writeBuffer(result, name, output);
    if (!options.statsPath.empty()) writeStatsJson(options.statsPath, description, result.stats);
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  printStats(std::cerr, description, result.stats);
  std::cerr << "wrote " << output.string() << "\n";
  return 0;
}

int validate(const std::string& scenePath) {
  try {
    const Scene scene = loadScene(scenePath);
    std::cout << scene.source << ": ok (" << scene.shapes.size() << " objects, "
              << scene.lights.size() << " lights, " << scene.materials.size() << " materials)\n";
    return 0;
  } catch (const SceneError& error) {
    std::cerr << error.what() << "\n";
    return kExitBadInput;
  }
}

void listAlgorithms() {
  for (const Renderer* renderer : allRenderers()) {
    std::cout << renderer->name() << "\n    " << renderer->summary() << "\n    "
              << renderer->citation() << "\n";
  }
}

std::vector<std::string> algorithmNames() {
  std::vector<std::string> names;
  for (const Renderer* renderer : allRenderers()) names.emplace_back(renderer->name());
  return names;
}

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options) {
  CLI::App* command = app.add_subcommand("render", "Render a scene file to an image");
  command->add_option("scene", options.scenePath, "Scene file (YAML or JSON), or - to read stdin")
      ->required();
  command->add_option("-o,--output", options.output,
                      "Image to write: .png, .ppm or .exr (default: the scene's name, .png)");
  command->add_option("-a,--algorithm", options.algorithm, "Algorithm (see `rise algorithms`)")
      ->check(CLI::IsMember(algorithmNames()));
  command->add_option("--width", options.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command->add_option("--height", options.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command->add_option("--threads", options.threads, "Worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--max-depth", options.maxDepth,
                   "Longest ray path of the ray tracers; the primary ray is 1")
      ->check(CLI::Range(1, 64));
  command->add_option("--samples", options.samples,
                      "Samples a pixel (default: the scene's, or 1); alone, picks jittered")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--pattern", options.pattern,
                   "Where the samples go: none, regular, jittered, random or adaptive")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, SamplePattern>{{"none", SamplePattern::None},
                                               {"regular", SamplePattern::Regular},
                                               {"jittered", SamplePattern::Jittered},
                                               {"random", SamplePattern::Random},
                                               {"adaptive", SamplePattern::Adaptive}},
          CLI::ignore_case));
  command
      ->add_option("--filter", options.filter, "Reconstruction filter: box, tent or gaussian")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, FilterKind>{{"box", FilterKind::Box},
                                            {"tent", FilterKind::Tent},
                                            {"gaussian", FilterKind::Gaussian}},
          CLI::ignore_case));
  command->add_option("--threshold", options.adaptiveThreshold,
                      "Adaptive pattern: the corner difference that is refined (default 0.05)")
      ->check(CLI::PositiveNumber);
  command->add_option("--seed", options.seed,
                      "Seed of the random samples: the same seed, the same image");
  command
      ->add_option("--accel", options.accel,
                   "Acceleration structure: none, spheres, bvh (default) or embree")
      ->transform(CLI::CheckedTransformer(accelNamesToValues(), CLI::ignore_case));
  command
      ->add_option("--shading", options.shading,
                   "Visible-surface algorithms: flat, gouraud or phong (default)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, Shading>{{"flat", Shading::Flat},
                                         {"gouraud", Shading::Gouraud},
                                         {"phong", Shading::Phong}},
          CLI::ignore_case));
  command->add_flag("--no-cull", options.noCulling,
                    "Visible-surface algorithms: keep the back faces of solids");
  command
      ->add_option("--tessellation", options.tessellation,
                   "Visible-surface algorithms: a circle becomes 4 x N segments (default 8)")
      ->check(CLI::Range(1, 256));
  command
      ->add_option("--plane-size", options.planeSize,
                   "Visible-surface algorithms: the side of the square drawn for a plane "
                   "(default 1000)")
      ->check(CLI::PositiveNumber);
  command->add_option("--stats", options.statsPath, "Also write the time and counters as JSON");
  command
      ->add_option("--encoding", options.encoding,
                   "srgb (the display standard) or linear (raw values)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, Encoding>{{"srgb", Encoding::Srgb}, {"linear", Encoding::Linear}},
          CLI::ignore_case));
  command
      ->add_option("--aov", options.buffers,
                   "Auxiliary buffers to write beside the image: depth, normal, cost, face "
                   "(face: the visible-surface algorithms only)")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal", "cost", "face"}));
  return command;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"RISE, the Realistic Image Synthesis Environment", "rise"};
  app.require_subcommand(1);

  RenderOptions renderOptions;
  const CLI::App* renderCommand = addRenderCommand(app, renderOptions);

  std::string validatePath;
  CLI::App* validateCommand =
      app.add_subcommand("validate", "Check a scene file without rendering it");
  validateCommand->add_option("scene", validatePath, "Scene file, or - to read stdin")->required();

  const CLI::App* algorithmsCommand =
      app.add_subcommand("algorithms", "List the algorithms, each with its citation");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitBadInput;
  }
  if (*renderCommand) return render(renderOptions);
  if (*validateCommand) return validate(validatePath);
  if (*algorithmsCommand) listAlgorithms();
  return 0;
}

}  // namespace rise::cli

int main(int argc, char** argv) { return rise::cli::run(argc, argv); }
