// `rise`: the command line of the Realistic Image Synthesis Environment. A thin
// layer over the library: it parses options, loads the scene, runs Renderers
// and writes what they returned.
//
// Exit status: 0 done, 1 an output file could not be written, 2 bad input
// (a scene file error or a wrong option); on status 2 no image is written.
#include "run.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <variant>

#include "algorithms/registry.hpp"
#include "animation.hpp"
#include "io/image_io.hpp"
#include "io/scene_error.hpp"
#include "job.hpp"
#include "look_inside.hpp"
#include "manual_command.hpp"
#include "progress_bar.hpp"
#include "render/buffer_images.hpp"
#include "reports/comparison_report.hpp"
#include "settings_options.hpp"
#include "stats_report.hpp"
#include "studio_command.hpp"
#include "tiles.hpp"

namespace rise::cli {
namespace {

struct RenderOptions {
  SettingsOptions settings;
  std::filesystem::path output;
  std::string algorithm = "ray-tracing";
  std::filesystem::path statsPath;
  Encoding encoding = Encoding::Srgb;
  std::vector<std::string> buffers;
  AnimationOptions animation;
};

struct CompareOptions {
  SettingsOptions settings;
  std::filesystem::path directory;
  std::vector<std::string> algorithms;  // empty: every one
  Encoding encoding = Encoding::Srgb;
};

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

int render(const RenderOptions& options, const CLI::App& command) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  const AlgorithmDescription& algorithm = renderer.description();
  if (!drawsShadowsAsked(algorithm, options.settings.request.settings.shadows))
    return kExitBadInput;
  for (const std::string& name : options.buffers) {
    if (!algorithm.writes(name)) {
      std::cerr << "rise: --aov " << name << ": " << algorithm.name << " has no '" << name
                << "' buffer; it has: " << joined(algorithm.buffers) << "\n";
      return kExitBadInput;
    }
    if (name == "shadow-map" && options.settings.request.settings.shadows != ShadowMethod::Map) {
      std::cerr << "rise: --aov shadow-map: there is no shadow map without --shadows map\n";
      return kExitBadInput;
    }
  }
  const std::filesystem::path output =
      options.output.empty() ? defaultOutput(options.settings.scenePath, ".png") : options.output;
  try {
    checkImageFormat(output);
  } catch (const ImageFileError& error) {
    std::cerr << "rise: -o " << error.what() << "\n";
    return kExitBadInput;
  }
  std::vector<PlannedOutput> outputs{{output, "-o"}};
  for (const std::string& name : options.buffers)
    outputs.push_back({bufferPath(output, name), "--aov " + name});
  if (!options.statsPath.empty()) outputs.push_back({options.statsPath, "--stats"});
  if (!outputsAreWritable(outputs, options.settings.scenePath)) return kExitBadInput;

  std::variant<Job, int> prepared = prepare(options.settings, {algorithm.family});
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  Job& job = std::get<Job>(prepared);
  noteUnreadOptions(command, algorithm);

  const std::optional<PixelRect>& tile = job.settings.region;
  const FrameWriter write = [&](const RenderResult& result, const std::filesystem::path& file) {
    const RenderDescription description = describe(job, renderer.name());
    try {
      writeImage(result.image, file, options.encoding);
      for (const std::string& name : options.buffers) writeBuffer(result, name, file);
      if (tile) writeTilePlace(file, job.settings, job.scene.source, renderer.name());
      if (!options.statsPath.empty()) writeStatsJson(options.statsPath, description, result.stats);
    } catch (const std::exception& error) {
      std::cerr << "rise: " << error.what() << "\n";
      return kExitOutputError;
    }
    printStats(std::cerr, description, result.stats);
    std::cerr << "wrote " << file.string() << "\n";
    return 0;
  };
  if (options.animation.requested()) {
    const std::filesystem::path pattern =
        options.output.empty() ? defaultFramePattern(options.settings.scenePath) : options.output;
    return renderFrames(renderer, job, options.animation, pattern, write);
  }
  const std::optional<RenderResult> rendered = renderWithProgress(renderer, job);
  if (!rendered) return kExitBadInput;
  return write(*rendered, !options.output.empty() ? options.output
                          : tile ? defaultTileOutput(options.settings.scenePath, *tile)
                                 : output);
}

int compare(const CompareOptions& options) {
  std::vector<const Renderer*> renderers;
  std::vector<std::string_view> names;
  std::vector<Family> families;
  for (const Renderer* renderer : allRenderers()) {
    if (!options.algorithms.empty() &&
        std::find(options.algorithms.begin(), options.algorithms.end(), renderer->name()) ==
            options.algorithms.end())
      continue;
    if (!drawsShadowsAsked(renderer->description(), options.settings.request.settings.shadows))
      return kExitBadInput;
    renderers.push_back(renderer);
    names.push_back(renderer->name());
    families.push_back(renderer->description().family);
  }
  const std::filesystem::path directory =
      options.directory.empty() ? defaultOutput(options.settings.scenePath, "") : options.directory;
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory)) {
    std::cerr << "rise: -o " << directory.string() << ": is a file; expected a folder to write "
              << "the comparison into\n";
    return kExitBadInput;
  }
  std::vector<PlannedOutput> outputs;
  for (const std::filesystem::path& file : comparisonFiles(directory, names))
    outputs.push_back({file, "-o " + directory.string() + " (" + file.filename().string() + ")"});
  if (!outputsAreWritable(outputs, options.settings.scenePath, true)) return kExitBadInput;

  std::variant<Job, int> prepared = prepare(options.settings, families);
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  const Job& job = std::get<Job>(prepared);

  std::vector<ComparedRender> renders;
  for (const Renderer* renderer : renderers) {
    std::optional<RenderResult> rendered = renderWithProgress(*renderer, job);
    if (!rendered) return kExitBadInput;
    renders.push_back({&renderer->description(), *std::move(rendered)});
    std::cerr << renderer->name() << ": " << renders.back().result.stats.value("render_seconds")
              << " s\n";
  }
  addSameImageCounters(renders, options.encoding);
  try {
    writeComparison(directory, job.scene.source, renders, options.encoding);
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << "wrote " << (directory / "index.html").string() << "\n";
  return 0;
}

// Loads the scene and checks that its own image can be rendered by every
// algorithm, as `rise render` would with no options.
int validate(const std::string& scenePath) {
  std::variant<Job, int> prepared =
      prepare({scenePath, {}}, {Family::VisibleSurface, Family::RayTracing});
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  const Scene& scene = std::get<Job>(prepared).scene;
  std::cout << scene.source << ": ok (" << scene.shapes.size() << " objects, "
            << scene.lights.size() << " lights, " << scene.materials.size() << " materials)\n";
  return 0;
}

void listAlgorithms() {
  for (const Renderer* renderer : allRenderers()) {
    const AlgorithmDescription& algorithm = renderer->description();
    std::vector<std::string_view> options, effects, shadows;
    for (Option option : algorithm.options) options.push_back(toString(option));
    for (Effect effect : algorithm.effects) effects.push_back(toString(effect));
    for (ShadowMethod method : algorithm.shadowMethods) shadows.push_back(shadowMethodName(method));
    std::cout << algorithm.name << "\n    " << algorithm.summary << "\n    " << algorithm.citation
              << "\n    family: " << toString(algorithm.family)
              << "\n    buffers: " << joined(algorithm.buffers)
              << "\n    options: " << joined(options) << "\n    effects: " << joined(effects)
              << "\n";
    if (!shadows.empty()) std::cout << "    shadows: " << joined(shadows) << "\n";
  }
}

// Every buffer some algorithm writes, in the order they are first met.
std::vector<std::string> bufferNames() {
  std::vector<std::string> names;
  for (const Renderer* renderer : allRenderers())
    for (std::string_view buffer : renderer->description().buffers)
      if (std::find(names.begin(), names.end(), buffer) == names.end()) names.emplace_back(buffer);
  return names;
}

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options) {
  CLI::App* command = app.add_subcommand("render", "Render a scene file to an image");
  addSettingsOptions(*command, options.settings);
  addTileOption(*command, options.settings);
  addAnimationOptions(*command, options.animation);
  command->add_option(
      "-o,--output", options.output,
      "Image to write: .png, .ppm or .exr (default: the scene's name, .png); with --frames, "
      "a pattern with the frame number: run_%04d.png");
  command->add_option("-a,--algorithm", options.algorithm, "Algorithm (see `rise algorithms`)")
      ->check(CLI::IsMember(algorithmNames()));
  command->add_option("--stats", options.statsPath, "Also write the time and counters as JSON");
  command
      ->add_option("--encoding", options.encoding,
                   "srgb (the display standard) or linear (raw values)")
      ->transform(encodings());
  command
      ->add_option("--aov", options.buffers,
                   "Auxiliary buffers to write beside the image (`rise algorithms` lists each "
                   "algorithm's): " +
                       joined(bufferNames()))
      ->delimiter(',')
      ->check(CLI::IsMember(bufferNames()));
  return command;
}

CLI::App* addCompareCommand(CLI::App& app, CompareOptions& options) {
  CLI::App* command = app.add_subcommand(
      "compare",
      "Render a scene with every algorithm: images, a table of times and counters "
      "(Markdown, CSV) and an HTML page");
  addSettingsOptions(*command, options.settings);
  command->add_option("-o,--output", options.directory,
                      "Folder to write into (default: the scene's name)");
  command
      ->add_option("--algorithms", options.algorithms,
                   "Only these algorithms, separated by commas (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(algorithmNames()));
  command
      ->add_option("--encoding", options.encoding,
                   "srgb (the display standard) or linear (raw values)")
      ->transform(encodings());
  return command;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"RISE, the Realistic Image Synthesis Environment", "rise"};
  app.require_subcommand(1);

  RenderOptions renderOptions;
  const CLI::App* renderCommand = addRenderCommand(app, renderOptions);
  CompareOptions compareOptions;
  const CLI::App* compareCommand = addCompareCommand(app, compareOptions);

  std::string validatePath;
  CLI::App* validateCommand =
      app.add_subcommand("validate", "Check a scene file without rendering it");
  validateCommand->add_option("scene", validatePath, "Scene file, or - to read stdin")->required();

  const CLI::App* algorithmsCommand =
      app.add_subcommand("algorithms", "List the algorithms, each with its citation");
  CLI::App* studioCommand = app.add_subcommand(
      "studio", "Open RISE Studio, the interactive window: rise studio [SCENE] [--script FILE]");
  studioCommand->prefix_command();
  const auto runLookInside = addLookInsideCommands(app);
  const auto runMerge = addMergeCommand(app);
  const auto runManual = addManualCommand(app);

  // CLI11 takes an unknown first word for a stray argument and asks for a
  // subcommand; say what was typed and what there is.
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  if (argc > 1 && argv[1][0] != '-' &&
      std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
    std::cerr << "rise: unknown command '" << argv[1] << "'; expected one of: " << joined(commands)
              << " (rise --help)\n";
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitBadInput;
  }
  if (*renderCommand) return render(renderOptions, *renderCommand);
  if (*compareCommand) return compare(compareOptions);
  if (*validateCommand) return validate(validatePath);
  if (*studioCommand) return startStudio(studioCommand->remaining());
  if (const std::optional<int> status = runLookInside()) return *status;
  if (const std::optional<int> status = runMerge()) return *status;
  if (const std::optional<int> status = runManual()) return *status;
  if (*algorithmsCommand) listAlgorithms();
  return 0;
}

}  // namespace rise::cli
