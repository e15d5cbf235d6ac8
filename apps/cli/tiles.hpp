// Splitting a render by hand: `rise render --tile X,Y,W,H` renders one region
// and writes, beside its image, where the region lies (a small JSON file, the
// image's name with ".tile.json" added); `rise merge DIR` joins the pieces a
// folder holds, refusing a set with a gap or an overlap.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <optional>

#include "render/render_settings.hpp"
#include "settings_options.hpp"

namespace rise::cli {

// The `--tile` option: its X,Y,W,H go into the request's region.
void addTileOption(CLI::App& command, SettingsOptions& options);

// A tile's default image, named after the scene and the region, in EXR so
// that the merge keeps the linear values.
std::filesystem::path defaultTileOutput(const std::string& scenePath, const PixelRect& region);

// Writes `image`'s place in the whole image beside it. Throws
// std::runtime_error when it cannot be written.
void writeTilePlace(const std::filesystem::path& image, const RenderSettings& settings,
                    const std::string& scene, std::string_view algorithm);

// Copies a tile's pixels into the whole image, at the tile's place.
void paste(const Image& tile, const PixelRect& place, Image& whole);

// The file that says where `image` lies.
std::filesystem::path tilePlacePath(const std::filesystem::path& image);

// Adds `rise merge`; the returned function runs it when it was chosen and
// returns its exit status, or returns nothing.
std::function<std::optional<int>()> addMergeCommand(CLI::App& app);

}  // namespace rise::cli
