// `rise explain` and `rise inspect`: an algorithm's steps as a page to step
// through, and the tree of rays behind one pixel.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>

namespace rise::cli {

// Adds the two commands to `app`; the returned function runs whichever was
// chosen and returns its exit status, or returns nothing when neither was.
std::function<std::optional<int>()> addLookInsideCommands(CLI::App& app);

}  // namespace rise::cli
