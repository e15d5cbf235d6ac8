// The largest files RISE reads. A file beyond them is refused before it is
// read whole, so that no input (a wrong file, /dev/zero, a stream that never
// ends) makes RISE read for minutes or fill the memory. The README lists them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>

namespace rise {

inline constexpr std::uintmax_t kLargestSceneFile = 16'000'000;
// A model of some millions of triangles; Assimp needs several times the file.
inline constexpr std::uintmax_t kLargestModelFile = 128'000'000;
inline constexpr std::uintmax_t kLargestImageFile = 128'000'000;
// An 8K texture (8192 x 4096): 400 MB as linear colours.
inline constexpr std::int64_t kMostImagePixels = 8192LL * 4096;

// "16 MB".
std::string megabytes(std::uintmax_t bytes);

// Why the file at `path`, if there is one, cannot be read whole: its links
// loop, it is a folder, not a regular file (a device, a pipe, which might
// never end), or larger than `limit`. Nothing when it can, or when it is
// missing (opening it says why). Every file RISE reads is asked first: the
// scene, and every model, image and side file (an OBJ's materials, a glTF's
// buffers) a file names.
std::optional<std::string> fileKindOrSizeProblem(const std::filesystem::path& path,
                                                 std::uintmax_t limit);

// All of a stream that ends within `limit` bytes; nothing when it holds more,
// having read little more than the limit.
std::optional<std::string> readAtMost(std::istream& in, std::uintmax_t limit);

}  // namespace rise
