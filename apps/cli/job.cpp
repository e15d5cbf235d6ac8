#include "job.hpp"

#include <iostream>

#include "algorithms/registry.hpp"
#include "io/scene_error.hpp"
#include "progress_bar.hpp"

namespace rise::cli {

std::variant<Job, int> prepare(const SettingsOptions& options) {
  Job job;
  try {
    job.scene = loadScene(options.scenePath);
    job.settings = settingsFor(job.scene, options.request);
  } catch (const SceneError& error) {
    std::cerr << error.what() << "\n";
    return kExitBadInput;
  } catch (const SettingsError& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitBadInput;
  }
  return job;
}

RenderResult renderWithProgress(const Renderer& renderer, const Job& job, StepRecorder* steps) {
  ProgressBar progress(std::string(renderer.name()), steps);
  return renderTimed(renderer, job.scene, job.settings, progress);
}

RenderDescription describe(const Job& job, std::string_view algorithm) {
  return {job.scene.source, std::string(algorithm), job.settings.width, job.settings.height,
          job.settings.threads};
}

std::filesystem::path defaultOutput(const std::string& scenePath, const std::string& extension) {
  if (scenePath == "-") return "render" + extension;
  return std::filesystem::path(scenePath).filename().replace_extension(extension);
}

void noteUnreadOptions(const CLI::App& command, const AlgorithmDescription& algorithm) {
  for (Option option : kAllOptions) {
    const std::string flag = "--" + std::string(toString(option));
    if (!algorithm.reads(option) && command.count(flag) > 0)
      std::cerr << "rise: note: " << algorithm.name << " does not read " << flag << "\n";
  }
}

std::vector<std::string> algorithmNames() {
  std::vector<std::string> names;
  for (const Renderer* renderer : allRenderers()) names.emplace_back(renderer->name());
  return names;
}

}  // namespace rise::cli
