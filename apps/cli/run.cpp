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
#include "compare.hpp"
#include "core/text.hpp"
#include "help_in_words.hpp"
#include "job.hpp"
#include "look_inside.hpp"
#include "manual_command.hpp"
#include "progress_bar.hpp"
#include "reference_image.hpp"
#include "render/render_limits.hpp"
#include "render_outputs.hpp"
#include "settings_options.hpp"
#include "stats_report.hpp"
#include "studio_command.hpp"
#include "tiles.hpp"

namespace rise::cli {
namespace {

struct RenderOptions {
  SettingsOptions settings;
  std::filesystem::path output;
  std::string algorithm{defaultRenderer(Use::Render).name()};
  RenderOutputOptions outputs;
  AnimationOptions animation;
  std::filesystem::path reference;  // empty: none
};

int render(const RenderOptions& options, const CLI::App& command) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  const AlgorithmDescription& algorithm = renderer.description();
  if (!drawsShadowsAsked(algorithm, options.settings.request.settings.shadows))
    return kExitBadInput;
  const std::optional<PixelRect>& tile = options.settings.request.settings.region;
  const std::filesystem::path output = !options.output.empty() ? options.output
                                       : tile ? defaultTileOutput(options.settings.scenePath, *tile)
                                              : defaultOutput(options.settings.scenePath, ".png");
  if (!renderOutputsAreValid(options.outputs, options.settings, algorithm, output))
    return kExitBadInput;

  std::variant<Job, int> prepared = prepare(options.settings, renderer);
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  Job& job = std::get<Job>(prepared);
  job.settings.buffers = options.outputs.buffers;  // those --aov writes, and no others
  std::optional<Image> reference;
  if (!options.reference.empty()) {
    reference = readReference(options.reference, job.settings);
    if (!reference) return kExitBadInput;
  }
  noteUnreadOptions(command, algorithm);

  const FrameWriter write = [&](const RenderResult& result, const std::filesystem::path& file) {
    const RenderDescription description = describe(job, renderer.name());
    try {
      writeRenderOutputs(result, file, options.outputs, description);
      if (tile) writeTilePlace(file, job.settings, job.scene.source, renderer.name());
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
  std::optional<RenderResult> rendered = renderWithProgress(renderer, job);
  if (!rendered) return kExitBadInput;
  if (reference) measureAgainst(*reference, *rendered);
  return write(*rendered, output);
}

int compare(const CompareOptions& options) {
  const std::variant<std::filesystem::path, int> directory = comparisonFolder(options);
  if (const int* status = std::get_if<int>(&directory)) return *status;
  const std::vector<const Renderer*> renderers = comparedRenderers(options);
  std::variant<Job, int> prepared = prepare(options.settings, renderers);
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
  return writeComparisonFolder(std::get<std::filesystem::path>(directory), job.scene.source,
                               renders, options.encoding);
}

// What each algorithm would say of rendering the job: nothing where it
// would render it, else why it refuses. Algorithms that say the same are
// named together: "ray-tracing, hybrid: a 640 x 480 image ... may trace up
// to ...".
struct Verdicts {
  std::vector<std::pair<std::string, std::vector<std::string_view>>> refusals;
  std::vector<std::string_view> able;
};

Verdicts verdictsOn(const Job& job) {
  Verdicts verdicts;
  for (const Renderer* renderer : allRenderers()) {
    try {
      checkRenderFits(job.scene, job.settings, *renderer);
      verdicts.able.push_back(renderer->name());
    } catch (const RenderLimitError& error) {
      const std::string message = error.what();
      const auto same = std::ranges::find_if(
          verdicts.refusals, [&](const auto& refusal) { return refusal.first == message; });
      if (same != verdicts.refusals.end())
        same->second.push_back(renderer->name());
      else
        verdicts.refusals.push_back({message, {renderer->name()}});
    }
  }
  return verdicts;
}

// Loads the scene and checks that its own image can be rendered by every
// algorithm, as `rise render -a ALGORITHM` would with no other option; names
// those that would refuse, and why.
int validate(const std::string& scenePath) {
  std::variant<Job, int> prepared = prepare({scenePath, {}}, std::span<const Renderer* const>{});
  if (const int* status = std::get_if<int>(&prepared)) return *status;
  const Job& job = std::get<Job>(prepared);
  const Scene& scene = job.scene;
  const Verdicts verdicts = verdictsOn(job);
  if (!verdicts.refusals.empty()) {
    std::cerr << "rise: " << scene.source << " loads, but not every algorithm would render it:\n";
    for (const auto& [message, names] : verdicts.refusals)
      std::cerr << "  " << joined(names) << ": " << message << "\n";
    if (!verdicts.able.empty()) std::cerr << "  " << joined(verdicts.able) << ": would render it\n";
    return kExitBadInput;
  }
  std::cout << scene.source << ": ok (" << counted(scene.shapes.size(), "object") << ", "
            << counted(scene.lights.size(), "light") << ", "
            << counted(scene.materials.size(), "material") << ")\n";
  return 0;
}

void listAlgorithms() {
  for (const Renderer* renderer : allRenderers()) {
    const AlgorithmDescription& algorithm = renderer->description();
    std::vector<std::string_view> options, effects, shadows, looks;
    for (Option option : algorithm.options)
      for (std::string_view flag : flagsOf(option)) options.push_back(flag);
    for (Look look : algorithm.looks) looks.push_back(toString(look));
    for (Effect effect : algorithm.effects) effects.push_back(toString(effect));
    for (ShadowMethod method : algorithm.shadowMethods) shadows.push_back(shadowMethodName(method));
    std::cout << algorithm.name << "\n    " << algorithm.summary << "\n    " << algorithm.citation
              << "\n    family: " << toString(algorithm.family)
              << "\n    buffers: " << joined(algorithm.buffers)
              << "\n    options: " << joined(options) << "\n    effects: " << joined(effects)
              << "\n    shows: " << joined(looks) << "\n";
    if (!shadows.empty()) std::cout << "    shadows: " << joined(shadows) << "\n";
  }
}

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options) {
  CLI::App* command = app.add_subcommand("render", "Render a scene file to an image");
  command->footer(
      "Examples:\n"
      "  rise render examples/classic.yaml -a z-buffer --width 320 -o z.png\n"
      "  rise render examples/spheres.yaml --samples 16 --aov depth,cost --stats stats.json -o "
      "s.png");
  addSettingsOptions(*command, options.settings);
  addTileOption(*command, options.settings);
  addAnimationOptions(*command, options.animation);
  command->add_option(
      "-o,--output", options.output,
      "Image to write: .png, .ppm or .exr (default: the scene's name, .png); with --frames, "
      "a pattern with the frame number: run_%04d.png");
  command->add_option("-a,--algorithm", options.algorithm, "Algorithm (see `rise algorithms`)")
      ->check(CLI::IsMember(algorithmNames()));
  addRenderOutputOptions(*command, options.outputs);
  addReferenceOption(*command, options.reference);
  return command;
}

CLI::App* addCompareCommand(CLI::App& app, CompareOptions& options) {
  CLI::App* command = app.add_subcommand(
      "compare",
      "Render a scene with every algorithm: images, a table of times and counters "
      "(Markdown, CSV) and an HTML page");
  addCompareOptions(*command, options);
  return command;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"RISE, the Realistic Image Synthesis Environment", "rise"};
  app.formatter(std::make_shared<HelpInWords>());
  app.set_version_flag("--version", "rise " RISE_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  rise render examples/classic.yaml -o classic.png       Whitted's ray tracer\n"
      "  rise render examples/classic.yaml -a scanline -o s.png  another algorithm\n"
      "  rise compare examples/classic.yaml -o compared          every algorithm, side by side\n"
      "  rise explain examples/classic.yaml -a area-subdivision  its steps, as a page to play\n"
      "Each command's options: rise COMMAND --help. The manual: rise manual");

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
