#include "settings_options.hpp"

#include <cmath>
#include <iostream>
#include <iterator>

#include "io/scene_file.hpp"
#include "ray/accelerator.hpp"
#include "render/tiles.hpp"

namespace rise::cli {
namespace {

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

// The image size: the scene's, unless the command line gives one; a single
// dimension keeps the scene's aspect ratio.
std::pair<int, int> imageSize(const SettingsOptions& options, const ImageSpec& image) {
  const double aspect = static_cast<double>(image.width) / image.height;
  if (options.width > 0 && options.height > 0) return {options.width, options.height};
  if (options.width > 0)
    return {options.width, std::max(1, static_cast<int>(std::lround(options.width / aspect)))};
  if (options.height > 0)
    return {std::max(1, static_cast<int>(std::lround(options.height * aspect))), options.height};
  return {image.width, image.height};
}

// The scene's pixel sampling with the command line's choices over it.
PixelSampling pixelSampling(const SettingsOptions& options, const PixelSampling& scene) {
  PixelSampling sampling = chooseSampling(scene, options.samples, options.pattern);
  if (options.filter) sampling.filter = *options.filter;
  if (options.adaptiveThreshold) sampling.adaptiveThreshold = *options.adaptiveThreshold;
  return sampling;
}

template <typename Enum>
CLI::CheckedTransformer choices(std::map<std::string, Enum> names) {
  return CLI::CheckedTransformer(std::move(names), CLI::ignore_case);
}

}  // namespace

void addSettingsOptions(CLI::App& command, SettingsOptions& options) {
  command.add_option("scene", options.scenePath, "Scene file (YAML or JSON), or - to read stdin")
      ->required();
  command.add_option("--width", options.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command.add_option("--height", options.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command.add_option("--threads", options.threads, "Worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  command
      .add_option("--max-depth", options.maxDepth,
                  "Longest ray path of the ray tracers; the primary ray is 1")
      ->check(CLI::Range(1, 64));
  command
      .add_option("--samples", options.samples,
                  "Samples a pixel (default: the scene's, or 1); alone, picks jittered")
      ->check(CLI::PositiveNumber);
  command
      .add_option("--pattern", options.pattern,
                  "Where the samples go: none, regular, jittered, random or adaptive")
      ->transform(choices<SamplePattern>({{"none", SamplePattern::None},
                                          {"regular", SamplePattern::Regular},
                                          {"jittered", SamplePattern::Jittered},
                                          {"random", SamplePattern::Random},
                                          {"adaptive", SamplePattern::Adaptive}}));
  command.add_option("--filter", options.filter, "Reconstruction filter: box, tent or gaussian")
      ->transform(choices<FilterKind>({{"box", FilterKind::Box},
                                       {"tent", FilterKind::Tent},
                                       {"gaussian", FilterKind::Gaussian}}));
  command
      .add_option("--threshold", options.adaptiveThreshold,
                  "Adaptive pattern: the corner difference that is refined (default 0.05)")
      ->check(CLI::PositiveNumber);
  command.add_option("--seed", options.seed,
                     "Seed of the random samples: the same seed, the same image");
  command
      .add_option("--accel", options.accel,
                  "Acceleration structure: none, spheres, bvh (default) or embree")
      ->transform(CLI::CheckedTransformer(accelNamesToValues(), CLI::ignore_case));
  command
      .add_option("--shading", options.shading,
                  "Visible-surface algorithms: flat, gouraud or phong (default)")
      ->transform(choices<Shading>(
          {{"flat", Shading::Flat}, {"gouraud", Shading::Gouraud}, {"phong", Shading::Phong}}));
  command.add_flag("--no-cull", options.noCulling,
                   "Visible-surface algorithms: keep the back faces of solids");
  command
      .add_option("--tessellation", options.tessellation,
                  "Visible-surface algorithms: a circle becomes 4 x N segments")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  command
      .add_option("--plane-size", options.planeSize,
                  "Visible-surface algorithms: the side of the square drawn for a plane")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

Scene loadScene(const std::string& path) {
  if (path != "-") return loadSceneFile(path);
  const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
  return rise::loadScene(text, "<stdin>");
}

std::variant<RenderSettings, std::string> makeSettings(const SettingsOptions& options,
                                                       const Scene& scene) {
  if (!isAvailable(options.accel))
    return "--accel " + std::string(accelName(options.accel)) +
           ": this build has no such structure (Embree was not found when it was built); "
           "available: " +
           availableAccelNames();
  RenderSettings settings;
  std::tie(settings.width, settings.height) = imageSize(options, scene.image);
  settings.threads = resolveThreadCount(options.threads);
  settings.maxDepth = options.maxDepth;
  settings.accel = options.accel;
  settings.sampling = pixelSampling(options, scene.image.sampling);
  settings.seed = options.seed;
  settings.shading = options.shading;
  settings.backfaceCulling = !options.noCulling;
  settings.tessellation = options.tessellation;
  settings.planeSize = options.planeSize;
  if (std::string problem = samplingProblem(settings.sampling); !problem.empty()) return problem;
  return settings;
}

}  // namespace rise::cli
