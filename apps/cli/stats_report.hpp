#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "core/stats.hpp"

namespace rise::cli {

// What a render was: which scene, which algorithm, at what size.
struct RenderDescription {
  std::string scene;
  std::string algorithm;
  int width;
  int height;
  int threads;
};

// The time and counters, one per line, aligned for reading on a terminal.
void printStats(std::ostream& out, const RenderDescription& render, const Stats& stats);

// The same as one flat JSON object: the description's fields, then every
// statistic by name, whole or not at all. Throws OutputFileError when the
// file cannot be written.
void writeStatsJson(const std::filesystem::path& path, const RenderDescription& render,
                    const Stats& stats);

}  // namespace rise::cli
