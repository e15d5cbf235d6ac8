// The temporary files of the outputs being written (atomic_file.hpp), removed
// when the process is interrupted (Ctrl-C, SIGINT) or told to stop (SIGTERM)
// while it writes, so that no half-written file is left behind; the process
// then ends by that signal, as it would have, with the status 130 or 143 a
// shell shows for it.
#pragma once

#include <filesystem>

namespace rise {

// Registers a temporary file to remove on interruption; the first call
// installs the handlers. At most kMostTemporaries at a time are registered
// (a render writes a handful of files at once); beyond them, a temporary is
// still removed when its write fails or ends, though not on interruption.
inline constexpr int kMostTemporaries = 64;
void registerTemporary(const std::filesystem::path& temporary);

// The temporary is in place or removed: nothing is left to remove.
void forgetTemporary(const std::filesystem::path& temporary);

}  // namespace rise
