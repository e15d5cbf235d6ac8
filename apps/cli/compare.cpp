#include "compare.hpp"

#include <algorithm>
#include <iostream>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "job.hpp"

namespace rise::cli {

void addCompareOptions(CLI::App& command, CompareOptions& options) {
  // A comparison sets each family at its best: the visible-surface
  // algorithms draw shadows, by the method all of them have.
  options.settings.request.settings.shadows = kComparedShadows;
  addSettingsOptions(command, options.settings);
  command.get_option("--shadows")
      ->description(
          "Visible-surface algorithms' shadows: shadow maps, shadow volumes (the scanline's "
          "alone: name it with --algorithms) or none (default map)");
  command.add_option("-o,--output", options.directory,
                     "Folder to write into (default: the scene's name)");
  command
      .add_option("--algorithms", options.algorithms,
                  "Only these algorithms, separated by commas (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(algorithmNames()));
  addEncodingOption(command, options.encoding);
}

std::vector<const Renderer*> comparedRenderers(const CompareOptions& options) {
  if (options.algorithms.empty()) return {allRenderers().begin(), allRenderers().end()};
  std::vector<const Renderer*> renderers;
  for (const Renderer* renderer : allRenderers())
    if (std::ranges::find(options.algorithms, renderer->name()) != options.algorithms.end())
      renderers.push_back(renderer);
  return renderers;
}

std::variant<std::filesystem::path, int> comparisonFolder(const CompareOptions& options) {
  for (const Renderer* renderer : comparedRenderers(options))
    if (!drawsShadowsAsked(renderer->description(), options.settings.request.settings.shadows))
      return kExitBadInput;
  const std::filesystem::path directory =
      options.directory.empty() ? defaultOutput(options.settings.scenePath, "") : options.directory;
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory)) {
    std::cerr << "rise: -o " << directory.string() << ": is a file; expected a folder to write "
              << "the comparison into\n";
    return kExitBadInput;
  }
  std::vector<std::string_view> names;
  for (const Renderer* renderer : comparedRenderers(options)) names.push_back(renderer->name());
  std::vector<PlannedOutput> outputs;
  for (const std::filesystem::path& file : comparisonFiles(directory, names))
    outputs.push_back({file, "-o " + directory.string() + " (" + file.filename().string() + ")"});
  if (!outputsAreWritable(outputs, options.settings.scenePath, true)) return kExitBadInput;
  return directory;
}

int writeComparisonFolder(const std::filesystem::path& directory, const std::string& sceneName,
                          std::vector<ComparedRender>& renders, Encoding encoding) {
  addSameImageCounters(renders, encoding);
  try {
    writeComparison(directory, sceneName, renders, encoding);
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << "wrote " << (directory / "index.html").string() << "\n";
  return 0;
}

}  // namespace rise::cli
