// The smallest PNG file a header check reads: the signature and the header
// chunk of an image of width x height RGB pixels, with no pixels after it.
#pragma once

#include <cstdint>
#include <string>

namespace rise {

inline std::string pngHeader(std::uint32_t width, std::uint32_t height) {
  const auto bigEndian = [](std::uint32_t value) {
    return std::string{static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                       static_cast<char>(value >> 8), static_cast<char>(value)};
  };
  return std::string("\x89PNG\r\n\x1a\n", 8) + bigEndian(13) + "IHDR" + bigEndian(width) +
         bigEndian(height) + std::string("\x08\x02\x00\x00\x00", 5) + bigEndian(0);
}

}  // namespace rise
