#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "algorithms/settings_for_scene.hpp"
#include "io/image_io.hpp"

namespace rise::cli {

// What every command that renders takes: the scene, and the request over it.
struct SettingsOptions {
  std::string scenePath;
  RenderRequest request;
};

// Adds the scene and one option for each setting a render takes.
void addSettingsOptions(CLI::App& command, SettingsOptions& options);

// The --encoding option's names: srgb, linear.
CLI::Validator encodings();

// Adds --encoding, how the images written store their values.
void addEncodingOption(CLI::App& command, Encoding& encoding);

// Reads the scene file, or standard input for "-". Throws SceneError.
Scene loadScene(const std::string& path);

}  // namespace rise::cli
