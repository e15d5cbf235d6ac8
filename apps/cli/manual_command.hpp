// `rise manual`: opens the book built by `cmake --build build --target manual`
// in the reader's browser, or prints where it is.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>

namespace rise::cli {

// Adds the command to `app`; the returned function runs it when it was chosen
// and returns its exit status, or returns nothing when it was not.
std::function<std::optional<int>()> addManualCommand(CLI::App& app);

}  // namespace rise::cli
