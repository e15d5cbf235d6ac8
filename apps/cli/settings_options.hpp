#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "render/renderer.hpp"

namespace rise::cli {

// What every command that renders takes: the scene, and how to render it.
// Unset values leave the scene's own choice.
struct SettingsOptions {
  std::string scenePath;
  int width = 0;  // 0: as the scene says
  int height = 0;
  int threads = 0;
  int maxDepth = 5;
  Accel accel = Accel::Bvh;
  std::optional<int> samples;
  std::optional<SamplePattern> pattern;
  std::optional<FilterKind> filter;
  std::optional<float> adaptiveThreshold;
  std::uint64_t seed = 0;
  Shading shading = Shading::Phong;
  bool noCulling = false;
  int tessellation = kDefaultTessellationLevel;
  float planeSize = kDefaultPlaneSize;
};

void addSettingsOptions(CLI::App& command, SettingsOptions& options);

// Reads the scene file, or standard input for "-". Throws SceneError.
Scene loadScene(const std::string& path);

// The settings for rendering `scene`, or what is wrong with the options.
std::variant<RenderSettings, std::string> makeSettings(const SettingsOptions& options,
                                                       const Scene& scene);

}  // namespace rise::cli
