#include "job.hpp"

#include <iostream>

#include "algorithms/registry.hpp"
#include "core/text.hpp"
#include "io/scene_error.hpp"
#include "progress_bar.hpp"
#include "render/render_limits.hpp"

namespace rise::cli {

std::variant<Job, int> prepare(const SettingsOptions& options,
                               std::span<const Renderer* const> renderers) {
  Job job;
  try {
    job.scene = loadScene(options.scenePath);
    for (const std::string& warning : job.scene.warnings) std::cerr << warning << "\n";
    job.settings = settingsFor(job.scene, options.request);
    for (const Renderer* renderer : renderers) checkRenderFits(job.scene, job.settings, *renderer);
  } catch (const SceneError& error) {
    std::cerr << error.what() << "\n";
    return kExitBadInput;
  } catch (const std::runtime_error& error) {  // SettingsError, RenderLimitError
    std::cerr << "rise: " << error.what() << "\n";
    return kExitBadInput;
  }
  return job;
}

std::variant<Job, int> prepare(const SettingsOptions& options, const Renderer& renderer) {
  const Renderer* const renderers[] = {&renderer};
  return prepare(options, renderers);
}

bool outputsAreWritable(const std::vector<PlannedOutput>& outputs, const std::string& scenePath,
                        bool foldersAreMade) {
  const std::string problem = outputsProblem(outputs, scenePath, foldersAreMade);
  if (!problem.empty()) std::cerr << "rise: " << problem << "\n";
  return problem.empty();
}

std::optional<RenderResult> renderWithProgress(const Renderer& renderer, const Job& job,
                                               StepRecorder* steps) {
  try {
    ProgressBar progress(std::string(renderer.name()), steps);
    return renderTimed(renderer, job.scene, job.settings, progress);
  } catch (const RenderLimitError& error) {  // the bar is erased by now
    std::cerr << "rise: " << error.what() << "\n";
    return std::nullopt;
  }
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
    if (algorithm.reads(option)) continue;
    for (std::string_view name : flagsOf(option)) {
      const std::string flag = "--" + std::string(name);
      if (command.count(flag) > 0)
        std::cerr << "rise: note: " << algorithm.name << " does not read " << flag << "\n";
    }
  }
}

bool drawsShadowsAsked(const AlgorithmDescription& algorithm, ShadowMethod method) {
  if (!algorithm.reads(Option::Shadows) || algorithm.draws(method)) return true;
  std::vector<std::string_view> able;
  for (const Renderer* renderer : allRenderers())
    if (renderer->description().reads(Option::Shadows) && renderer->description().draws(method))
      able.push_back(renderer->name());
  std::cerr << "rise: --shadows " << shadowMethodName(method) << ": " << algorithm.name
            << " does not draw these shadows; "
            << (able.empty() ? "no algorithm does" : "only " + joined(able) + " does") << "\n";
  return false;
}

std::vector<std::string> algorithmNames() {
  std::vector<std::string> names;
  for (const Renderer* renderer : allRenderers()) names.emplace_back(renderer->name());
  return names;
}

}  // namespace rise::cli
