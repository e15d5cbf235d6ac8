// What `rise render` writes besides the image, and how it checks the files
// before it renders: the auxiliary buffers (--aov), each beside the image,
// and the time and counters as JSON (--stats). `rise render` and `rise-mpi
// render` take these options and write them the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "render/renderer.hpp"
#include "settings_options.hpp"
#include "stats_report.hpp"

namespace rise::cli {

struct RenderOutputOptions {
  std::filesystem::path statsPath;  // empty: none
  Encoding encoding = Encoding::Srgb;
  std::vector<std::string> buffers;
};

// Adds --stats, --encoding and --aov.
void addRenderOutputOptions(CLI::App& command, RenderOutputOptions& options);

// Says what is wrong with the files a render of `algorithm` to `image`
// would write (a buffer the algorithm has not, an image format unknown, a
// file that cannot be written); true when nothing is.
bool renderOutputsAreValid(const RenderOutputOptions& options, const SettingsOptions& settings,
                           const AlgorithmDescription& algorithm,
                           const std::filesystem::path& image);

// Writes the image, the buffers beside it and the statistics. Throws when a
// file cannot be written.
void writeRenderOutputs(const RenderResult& result, const std::filesystem::path& image,
                        const RenderOutputOptions& options, const RenderDescription& description);

}  // namespace rise::cli
