// What the commands that render share: the scene and settings a command's
// options make, the render with a progress bar, and the exit statuses.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "output_check.hpp"
#include "render/renderer.hpp"
#include "settings_options.hpp"
#include "stats_report.hpp"

namespace rise::cli {

inline constexpr int kExitOutputError = 1;
inline constexpr int kExitBadInput = 2;

// A scene and the settings to render it with.
struct Job {
  Scene scene;
  RenderSettings settings;
};

// The job the options ask for, or the exit status of the message already
// printed about them: refused when a render by one of `renderers` would
// exceed its limits (render/render_limits.hpp).
std::variant<Job, int> prepare(const SettingsOptions& options,
                               std::span<const Renderer* const> renderers);
// The same for a render by `renderer` alone.
std::variant<Job, int> prepare(const SettingsOptions& options, const Renderer& renderer);

// Says what is wrong with the files a command will write, before it renders.
bool outputsAreWritable(const std::vector<PlannedOutput>& outputs, const std::string& scenePath,
                        bool foldersAreMade = false);

// Renders with a progress bar, and the steps recorded in `steps` when given;
// nothing when the render would exceed a limit of its work (said).
std::optional<RenderResult> renderWithProgress(const Renderer& renderer, const Job& job,
                                               StepRecorder* steps = nullptr);

RenderDescription describe(const Job& job, std::string_view algorithm);

// The scene file's name with another extension, in the current folder.
std::filesystem::path defaultOutput(const std::string& scenePath, const std::string& extension);

// Says which of the options given the algorithm does not read.
void noteUnreadOptions(const CLI::App& command, const AlgorithmDescription& algorithm);

// Whether the algorithm draws the shadows --shadows asks for, or does not
// read the option; when not, says so and which algorithms do.
bool drawsShadowsAsked(const AlgorithmDescription& algorithm, ShadowMethod method);

std::vector<std::string> algorithmNames();

}  // namespace rise::cli
