// The image loaders: RISE's own PCX reader, stb_image's formats and OpenEXR
// behind RISE's checks of their headers. Any file must end in an image or an ImageFileError.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "input_file.hpp"
#include "io/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static constexpr std::array kExtensions{".pcx", ".png", ".tga", ".bmp", ".hdr", ".ppm", ".jpg", ".exr"};
  const std::filesystem::path path = rise::fuzz::writeInputFile(data, size, kExtensions);
  std::vector<std::string> warnings;
  try {
    rise::readImage(path, rise::Encoding::Srgb, &warnings);
  } catch (const rise::ImageFileError&) {
  }
  return 0;
}
