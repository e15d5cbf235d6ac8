// `rise compare`: every algorithm, or those chosen, on one scene, written as
// the images, the table of times and counters and the page that
// reports/comparison_report.hpp makes. `rise compare` renders the algorithms
// one after the other; `rise-mpi compare` spreads them over the ranks of an
// MPI run: both take these options, check and write the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "reports/comparison_report.hpp"
#include "settings_options.hpp"

namespace rise::cli {

struct CompareOptions {
  SettingsOptions settings;
  std::filesystem::path directory;
  std::vector<std::string> algorithms;  // empty: every one
  Encoding encoding = Encoding::Srgb;
};

// Adds the scene, the settings, -o, --algorithms and --encoding.
void addCompareOptions(CLI::App& command, CompareOptions& options);

// The algorithms the options choose, in the registry's order.
std::vector<const Renderer*> comparedRenderers(const CompareOptions& options);

// Their families, for the checks of the limits of a render.

// The folder the comparison goes into, or the exit status of the message
// printed when it, or a file in it, cannot be written, or when an algorithm
// compared does not draw the shadows asked for.
std::variant<std::filesystem::path, int> comparisonFolder(const CompareOptions& options);

// Adds the counters that set algorithms side by side and writes the folder;
// returns the exit status.
int writeComparisonFolder(const std::filesystem::path& directory, const std::string& sceneName,
                          std::vector<ComparedRender>& renders, Encoding encoding);

}  // namespace rise::cli
