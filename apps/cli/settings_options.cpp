#include "settings_options.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <vector>

#include "core/text.hpp"
#include "io/scene_file.hpp"
#include "job.hpp"
#include "option_checks.hpp"
#include "render/render_limits.hpp"

namespace rise::cli {
namespace {

// The value named, in any case; a name not among them is refused with the
// names there are: "--accel: bhv; expected one of bvh, embree, none, spheres".
template <typename Enum>
CLI::Validator choices(std::map<std::string, Enum> names) {
  std::vector<std::string> nameList;
  for (const auto& entry : names) nameList.push_back(entry.first);
  const std::string expected = joined(nameList);
  const CLI::CheckedTransformer named(std::move(names), CLI::ignore_case);
  return CLI::Validator(
      [named, expected](std::string& text) -> std::string {
        const std::string given = text;
        if (named(text).empty()) return {};
        return given + "; expected one of " + expected;
      },
      "{" + expected + "}");
}

CLI::Validator finitePositiveNumber() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && std::isfinite(value) &&
            value > 0.0)
          return {};
        return text + "; expected a finite number > 0";
      },
      "> 0");
}

// The values of an enumeration by their names on the command line.
template <typename Enum, std::size_t Count, typename Name>
CLI::Validator choicesNamedBy(const Enum (&all)[Count], Name name) {
  std::map<std::string, Enum> names;
  for (Enum value : all) names.emplace(name(value), value);
  return choices(std::move(names));
}

void addShadowOptions(CLI::App& command, RenderSettings& settings) {
  command
      .add_option("--shadows", settings.shadows,
                  "Visible-surface algorithms' shadows: shadow maps, shadow volumes (the "
                  "scanline's) or none (default none)")
      ->transform(choicesNamedBy(kAllShadowMethods, shadowMethodName));
  command.add_option("--shadow-map-size", settings.shadowMapSize, "Shadow maps: texels a side")
      ->capture_default_str()
      ->check(wholeNumberFrom(16, 8192));
  command
      .add_option("--shadow-bias", settings.shadowBias,
                  "Shadow maps: the bias in texels, scaled by the surface's slope")
      ->capture_default_str()
      ->check(numberFrom(0.0, 1000.0));
  command
      .add_option("--shadow-filter", settings.shadowFilter,
                  "Shadow maps: percentage-closer filtering over (2 R + 1)^2 texels; 0: none")
      ->capture_default_str()
      ->check(wholeNumberFrom(0, 16));
}

void addPathOptions(CLI::App& command, RenderSettings& settings) {
  command
      .add_option("--light-sampling", settings.lightSampling,
                  "Path tracing: finds the lights by shadow rays (nee), by its BRDF's samples "
                  "(brdf) or both, weighted (mis, the default)")
      ->transform(choicesNamedBy(kAllLightSamplings, lightSamplingName));
  command.add_flag("--no-roulette{false}", settings.russianRoulette,
                   "Path tracing: follow every path to --max-depth, without Russian roulette");
  command
      .add_option("--time-limit", settings.progression.timeLimit,
                  "Path tracing: stop refining after about this many seconds")
      ->check(finitePositiveNumber());
  command
      .add_option("--noise-target", settings.progression.noiseTarget,
                  "Path tracing: stop refining when the estimated noise (relative standard "
                  "error) falls to this, e.g. 0.01")
      ->check(finitePositiveNumber());
}

void addRadiosityOptions(CLI::App& command, RadiositySettings& settings) {
  command
      .add_option("--patch-size", settings.patchSize,
                  "Radiosity: the side of the patches the light is solved between (default: "
                  "what keeps them at most 3,000)")
      ->check(finitePositiveNumber());
  command
      .add_option("--residual", settings.residual,
                  "Radiosity: solve until the light still to pass on is this share of the "
                  "sources'")
      ->capture_default_str()
      ->check(numberFrom(1e-6, 1.0));
  command
      .add_option("--solver", settings.solver,
                  "Radiosity: progressive refinement (progressive, the default) or "
                  "gauss-seidel")
      ->transform(choicesNamedBy(kAllRadiositySolvers, radiositySolverName));
  command
      .add_option("--form-factors", settings.formFactors,
                  "Radiosity: in closed form with a ray for visibility (rays, the default) or by "
                  "a hemicube over each patch (hemicube)")
      ->transform(choicesNamedBy(kAllFormFactorMethods, formFactorMethodName));
  command
      .add_option("--hemicube-size", settings.hemicubeSize,
                  "Radiosity: the texels a side of the hemicube's top face")
      ->capture_default_str()
      ->check(wholeNumberFrom(8, 1024));
  command
      .add_option("--display", settings.display,
                  "Radiosity: the visible-surface algorithm that draws the solution (z-buffer, the "
                  "default, scanline, depth-sort or area-subdivision)")
      ->transform(choicesNamedBy(kAllRadiosityDisplays, radiosityDisplayName));
}

}  // namespace

void addSettingsOptions(CLI::App& command, SettingsOptions& options) {
  RenderSettings& settings = options.request.settings;
  ImageOverrides& image = options.request.image;
  command.add_option("scene", options.scenePath, "Scene file (YAML or JSON), or - to read stdin")
      ->required();
  command.add_option("--width", image.width, "Image width in pixels (default: the scene's)")
      ->check(wholeNumberFrom(1, kLargestImageSide));
  command.add_option("--height", image.height, "Image height in pixels (default: the scene's)")
      ->check(wholeNumberFrom(1, kLargestImageSide));
  command.add_option("--threads", settings.threads, "Worker threads (default: one per core)")
      ->check(wholeNumberFrom(0, kMostThreads));
  command
      .add_option("--max-depth", settings.maxDepth,
                  "Longest ray path of the ray tracers; the primary ray is 1")
      ->capture_default_str()
      ->check(wholeNumberFrom(1, 64));
  command
      .add_option("--samples", image.samples,
                  "Samples a pixel (default: the scene's, or 1); alone, picks jittered")
      ->check(wholeNumberFrom(1, kMostSamples));
  command.add_option("--pattern", image.pattern, "Where the samples go in a pixel")
      ->transform(choices<SamplePattern>({{"none", SamplePattern::None},
                                          {"regular", SamplePattern::Regular},
                                          {"jittered", SamplePattern::Jittered},
                                          {"random", SamplePattern::Random},
                                          {"adaptive", SamplePattern::Adaptive}}));
  command.add_option("--filter", image.filter, "Reconstruction filter")
      ->transform(choices<FilterKind>({{"box", FilterKind::Box},
                                       {"tent", FilterKind::Tent},
                                       {"gaussian", FilterKind::Gaussian}}));
  command
      .add_option("--threshold", image.adaptiveThreshold,
                  "Adaptive pattern: the corner difference that is refined (default 0.05)")
      ->check(finitePositiveNumber());
  command
      .add_option("--seed", settings.seed,
                  "Seed of the random samples: the same seed, the same image")
      ->check(wholeNumberFrom<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
  command
      .add_option("--accel", settings.accel,
                  "Acceleration structure of the ray tracers (default bvh)")
      ->transform(choicesNamedBy(kAllAccels, accelName));
  command
      .add_option("--shading", settings.shading,
                  "Visible-surface algorithms' shading (default phong)")
      ->transform(choices<Shading>(
          {{"flat", Shading::Flat}, {"gouraud", Shading::Gouraud}, {"phong", Shading::Phong}}));
  command.add_flag("--no-cull{false}", settings.backfaceCulling,
                   "Visible-surface algorithms: keep the back faces of solids");
  command
      .add_option("--tessellation", settings.tessellation,
                  "Visible-surface algorithms: a circle becomes 4 x N segments")
      ->capture_default_str()
      ->check(wholeNumberFrom(1, 256));
  command
      .add_option("--plane-size", settings.planeSize,
                  "Visible-surface algorithms: the side of the square drawn for a plane")
      ->capture_default_str()
      ->check(finitePositiveNumber());
  addShadowOptions(command, settings);
  command
      .add_option("--transparency", settings.transparency,
                  "z-buffer: transparent surfaces sorted back to front or by the a-buffer's "
                  "fragment lists (default sorted)")
      ->transform(choicesNamedBy(kAllTransparencies, transparencyName));
  addPathOptions(command, settings);
  addRadiosityOptions(command, settings.radiosity);
}

CLI::Validator encodings() {
  return choices(
      std::map<std::string, Encoding>{{"srgb", Encoding::Srgb}, {"linear", Encoding::Linear}});
}

void addEncodingOption(CLI::App& command, Encoding& encoding) {
  command.add_option("--encoding", encoding, "srgb (the display standard) or linear (raw values)")
      ->transform(encodings());
}

Scene loadScene(const std::string& path) {
  if (path != "-") return loadSceneFile(path);
  // A folder opens as standard input and reads as nothing, an empty scene.
  struct stat standardInput {};
  if (fstat(STDIN_FILENO, &standardInput) == 0 && S_ISDIR(standardInput.st_mode))
    throw SceneError("<stdin>",
                     "standard input is a folder; expected a scene (rise render - < "
                     "scene.yaml)");
  return loadSceneStream(std::cin, "<stdin>");
}

}  // namespace rise::cli
