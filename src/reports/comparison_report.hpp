#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "io/image_io.hpp"
#include "render/renderer.hpp"

namespace rise {

// The comparison of algorithms on one scene that `rise compare` writes and
// the studio shows and writes: apart from both front ends, above the
// registry, as it reports on renders (io/, which reads and writes files, is
// below the render layer whose results it would need).

// One algorithm's render of the compared scene.
struct ComparedRender {
  const AlgorithmDescription* algorithm;
  RenderResult result;
};

// Every statistic any of the renders reported, in the order they first
// appear: the rows of the comparison's table.
std::vector<std::string> statisticNames(const std::vector<ComparedRender>& renders);

// A statistic as the table shows it ("" when the render has none): whole
// numbers in full, others to four significant digits.
std::string statisticCell(const Stats& stats, const std::string& name);

// Beside each algorithm that renders another's image by other means
// (AlgorithmDescription::sameImageAs), when that one was rendered too: the
// pixels where the two images, stored with `encoding`, differ by more than 2
// of the 256 levels in some channel, "pixels_differing_from_<other>"; the
// intersection tests it saved, "intersection_tests_saved"; and how many times
// faster it was, "speedup_over_<other>".
void addSameImageCounters(std::vector<ComparedRender>& renders, Encoding encoding);

// The files writeComparison writes for these algorithms, images first.
std::vector<std::filesystem::path> comparisonFiles(const std::filesystem::path& directory,
                                                   const std::vector<std::string_view>& algorithms);

// Writes, into `directory`, each algorithm's image (<algorithm>.png), the
// times and counters of all of them as results.csv (one row an algorithm)
// and results.md (one row a counter, one column an algorithm, for reading),
// and index.html, which shows the images side by side above the table and a
// bar chart of the times, each file whole or not at all. Returns the files
// written. Throws ImageFileError, OutputFileError or std::runtime_error when
// a file cannot be written.
std::vector<std::filesystem::path> writeComparison(const std::filesystem::path& directory,
                                                   const std::string& sceneName,
                                                   const std::vector<ComparedRender>& renders,
                                                   Encoding encoding);

}  // namespace rise
