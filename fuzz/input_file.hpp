// The fuzzers' way into the loaders that read files: the input written to a
// file of the format its first byte picks, in a folder of the fuzzer's own.
#pragma once

#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace rise::fuzz {

// The file the rest of the input is written to, named with the extension
// the first byte picks out of `extensions` (".md2", ".pcx", ...).
template <std::size_t N>
std::filesystem::path writeInputFile(const std::uint8_t* data, std::size_t size,
                                     const std::array<const char*, N>& extensions) {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("rise-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const char* extension = extensions[size == 0 ? 0 : data[0] % N];
  const std::filesystem::path path = folder / (std::string("input") + extension);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (size > 1)
    file.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  return path;
}

}  // namespace rise::fuzz
