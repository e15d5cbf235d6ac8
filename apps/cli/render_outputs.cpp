#include "render_outputs.hpp"

#include <algorithm>
#include <iostream>

#include "algorithms/registry.hpp"
#include "core/text.hpp"
#include "io/scene_error.hpp"
#include "job.hpp"
#include "render/buffer_images.hpp"
#include "tiles.hpp"

namespace rise::cli {
namespace {

// out.png -> out.depth.png: the auxiliary buffers are written beside the image.
std::filesystem::path bufferPath(const std::filesystem::path& output, const std::string& name) {
  std::filesystem::path path = output;
  return path.replace_extension("." + name + output.extension().string());
}

// EXR keeps the raw values; the 8-bit formats get a picture of them.
void writeBuffer(const RenderResult& result, const std::string& name,
                 const std::filesystem::path& output) {
  const Image& raw = result.buffers.find(name)->second;
  const std::filesystem::path path = bufferPath(output, name);
  if (output.extension() == ".exr")
    writeImage(raw, path, Encoding::Linear);
  else
    writeImage(visualizeBuffer(name, raw), path, Encoding::Linear);
}

// Every buffer some algorithm writes, in the order they are first met.
std::vector<std::string> bufferNames() {
  std::vector<std::string> names;
  for (const Renderer* renderer : allRenderers())
    for (std::string_view buffer : renderer->description().buffers)
      if (std::find(names.begin(), names.end(), buffer) == names.end()) names.emplace_back(buffer);
  return names;
}

bool buffersAreWritten(const RenderOutputOptions& options, const SettingsOptions& settings,
                       const AlgorithmDescription& algorithm) {
  for (const std::string& name : options.buffers) {
    if (!algorithm.writes(name)) {
      std::cerr << "rise: --aov " << name << ": " << algorithm.name << " has no '" << name
                << "' buffer; it has: " << joined(algorithm.buffers) << "\n";
      return false;
    }
    if (name == "shadow-map" && settings.request.settings.shadows != ShadowMethod::Map) {
      std::cerr << "rise: --aov shadow-map: there is no shadow map without --shadows map\n";
      return false;
    }
  }
  return true;
}

}  // namespace

void addRenderOutputOptions(CLI::App& command, RenderOutputOptions& options) {
  command.add_option("--stats", options.statsPath, "Also write the time and counters as JSON");
  addEncodingOption(command, options.encoding);
  command
      .add_option("--aov", options.buffers,
                  "Auxiliary buffers to write beside the image (`rise algorithms` lists each "
                  "algorithm's)")
      ->delimiter(',')
      ->check(CLI::IsMember(bufferNames()));
}

bool renderOutputsAreValid(const RenderOutputOptions& options, const SettingsOptions& settings,
                           const AlgorithmDescription& algorithm,
                           const std::filesystem::path& image) {
  if (!buffersAreWritten(options, settings, algorithm)) return false;
  try {
    checkImageFormat(image);
  } catch (const ImageFileError& error) {
    std::cerr << "rise: -o " << error.what() << "\n";
    return false;
  }
  std::vector<PlannedOutput> outputs{{image, "-o"}};
  for (const std::string& name : options.buffers)
    outputs.push_back({bufferPath(image, name), "--aov " + name});
  if (!options.statsPath.empty()) outputs.push_back({options.statsPath, "--stats"});
  if (settings.request.settings.region) outputs.push_back({tilePlacePath(image), "--tile's place"});
  return outputsAreWritable(outputs, settings.scenePath);
}

void writeRenderOutputs(const RenderResult& result, const std::filesystem::path& image,
                        const RenderOutputOptions& options, const RenderDescription& description) {
  writeImage(result.image, image, options.encoding);
  for (const std::string& name : options.buffers) writeBuffer(result, name, image);
  if (!options.statsPath.empty()) writeStatsJson(options.statsPath, description, result.stats);
}

}  // namespace rise::cli
