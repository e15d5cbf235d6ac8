#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "io/image_io.hpp"
#include "render/renderer.hpp"

namespace rise::cli {

// One algorithm's render of the compared scene.
struct ComparedRender {
  const AlgorithmDescription* algorithm;
  RenderResult result;
};

// Writes, into `directory`, each algorithm's image (<algorithm>.png), the
// times and counters of all of them as results.csv (one row an algorithm)
// and results.md (one row a counter, one column an algorithm, for reading),
// and index.html, which shows the images side by side above the table and a
// bar chart of the times, each file whole or not at all. Returns the files
// written. Throws ImageFileError, OutputFileError or std::runtime_error when
// a file cannot be written.
// The files writeComparison writes for these algorithms, images first.
std::vector<std::filesystem::path> comparisonFiles(const std::filesystem::path& directory,
                                                   const std::vector<std::string_view>& algorithms);

std::vector<std::filesystem::path> writeComparison(const std::filesystem::path& directory,
                                                   const std::string& sceneName,
                                                   const std::vector<ComparedRender>& renders,
                                                   Encoding encoding);

}  // namespace rise::cli
