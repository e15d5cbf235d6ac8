// `rise render --reference IMAGE`: the render measured against an image of
// the same size, a converged render of many samples or another renderer's,
// its error added to the counters: how a student sees what more samples, or
// another way of finding the light, buy.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

#include "core/image.hpp"
#include "render/renderer.hpp"

namespace rise::cli {

// Adds --reference, which a still image of the whole frame takes (not
// --frames or --tile).
void addReferenceOption(CLI::App& command, std::filesystem::path& reference);

// The reference read and checked against the size the job renders at, or
// none once the message saying what is wrong with it is printed.
std::optional<Image> readReference(const std::filesystem::path& path,
                                   const RenderSettings& settings);

// Adds reference_rmse and reference_relative_error to the render's counters.
void measureAgainst(const Image& reference, RenderResult& result);

}  // namespace rise::cli
