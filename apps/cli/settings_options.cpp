#include "settings_options.hpp"

#include <iostream>
#include <iterator>

#include "io/scene_file.hpp"

namespace rise::cli {
namespace {

template <typename Enum>
CLI::CheckedTransformer choices(std::map<std::string, Enum> names) {
  return CLI::CheckedTransformer(std::move(names), CLI::ignore_case);
}

std::map<std::string, Accel> accelNames() {
  std::map<std::string, Accel> names;
  for (Accel accel : kAllAccels) names.emplace(accelName(accel), accel);
  return names;
}

void addShadowOptions(CLI::App& command, RenderSettings& settings) {
  command
      .add_option("--shadows", settings.shadows,
                  "Visible-surface algorithms' shadows: none (default) or map")
      ->transform(
          choices<ShadowMethod>({{"none", ShadowMethod::None}, {"map", ShadowMethod::Map}}));
  command.add_option("--shadow-map-size", settings.shadowMapSize, "Shadow maps: texels a side")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  command
      .add_option("--shadow-bias", settings.shadowBias,
                  "Shadow maps: the bias in texels, scaled by the surface's slope")
      ->capture_default_str()
      ->check(CLI::Range(0.0f, 1000.0f));
  command
      .add_option("--shadow-filter", settings.shadowFilter,
                  "Shadow maps: percentage-closer filtering over (2 R + 1)^2 texels; 0: none")
      ->capture_default_str()
      ->check(CLI::Range(0, 16));
}

}  // namespace

void addSettingsOptions(CLI::App& command, SettingsOptions& options) {
  RenderSettings& settings = options.request.settings;
  ImageOverrides& image = options.request.image;
  command.add_option("scene", options.scenePath, "Scene file (YAML or JSON), or - to read stdin")
      ->required();
  command.add_option("--width", image.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command.add_option("--height", image.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::PositiveNumber);
  command.add_option("--threads", settings.threads, "Worker threads (default: one per core)")
      ->check(CLI::NonNegativeNumber);
  command
      .add_option("--max-depth", settings.maxDepth,
                  "Longest ray path of the ray tracers; the primary ray is 1")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  command
      .add_option("--samples", image.samples,
                  "Samples a pixel (default: the scene's, or 1); alone, picks jittered")
      ->check(CLI::PositiveNumber);
  command
      .add_option("--pattern", image.pattern,
                  "Where the samples go: none, regular, jittered, random or adaptive")
      ->transform(choices<SamplePattern>({{"none", SamplePattern::None},
                                          {"regular", SamplePattern::Regular},
                                          {"jittered", SamplePattern::Jittered},
                                          {"random", SamplePattern::Random},
                                          {"adaptive", SamplePattern::Adaptive}}));
  command.add_option("--filter", image.filter, "Reconstruction filter: box, tent or gaussian")
      ->transform(choices<FilterKind>({{"box", FilterKind::Box},
                                       {"tent", FilterKind::Tent},
                                       {"gaussian", FilterKind::Gaussian}}));
  command
      .add_option("--threshold", image.adaptiveThreshold,
                  "Adaptive pattern: the corner difference that is refined (default 0.05)")
      ->check(CLI::PositiveNumber);
  command.add_option("--seed", settings.seed,
                     "Seed of the random samples: the same seed, the same image");
  command
      .add_option("--accel", settings.accel,
                  "Acceleration structure: none, spheres, bvh (default) or embree")
      ->transform(CLI::CheckedTransformer(accelNames(), CLI::ignore_case));
  command
      .add_option("--shading", settings.shading,
                  "Visible-surface algorithms: flat, gouraud or phong (default)")
      ->transform(choices<Shading>(
          {{"flat", Shading::Flat}, {"gouraud", Shading::Gouraud}, {"phong", Shading::Phong}}));
  command.add_flag("--no-cull{false}", settings.backfaceCulling,
                   "Visible-surface algorithms: keep the back faces of solids");
  command
      .add_option("--tessellation", settings.tessellation,
                  "Visible-surface algorithms: a circle becomes 4 x N segments")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  command
      .add_option("--plane-size", settings.planeSize,
                  "Visible-surface algorithms: the side of the square drawn for a plane")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  addShadowOptions(command, settings);
}

CLI::CheckedTransformer encodings() {
  return CLI::CheckedTransformer(
      std::map<std::string, Encoding>{{"srgb", Encoding::Srgb}, {"linear", Encoding::Linear}},
      CLI::ignore_case);
}

Scene loadScene(const std::string& path) {
  if (path != "-") return loadSceneFile(path);
  const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
  return rise::loadScene(text, "<stdin>");
}

}  // namespace rise::cli
