// Image files: PNG and PPM hold 8-bit display values, OpenEXR holds the
// renderer's linear floats unchanged (values above 1 included).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.hpp"

namespace rise {

// How linear colours become stored values: sRGB (the display standard, the
// default) or the raw linear values.
enum class Encoding { Srgb, Linear };

// The sRGB transfer functions of IEC 61966-2-1: a linear segment near black,
// then a 1/2.4 power curve. Both map [0, 1] onto [0, 1].
float srgbFromLinear(float linear);
float linearFromSrgb(float encoded);

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes the image as PNG, PPM (binary P6) or OpenEXR, chosen by the path's
// extension (.png, .ppm, .exr). Values are clamped to [0, 1], encoded and
// rounded to the nearest 8-bit level for PNG and PPM; OpenEXR always keeps
// the linear 32-bit floats and ignores the encoding. The file is written whole
// or not at all (a temporary file beside it, then a rename). Throws
// ImageFileError naming the path and the cause.
void writeImage(const Image& image, const std::filesystem::path& path,
                Encoding encoding = Encoding::Srgb);

// Throws the ImageFileError that writeImage would for a path whose extension
// names no format it writes, before anything is rendered for it.
void checkImageFormat(const std::filesystem::path& path);

// Reads an image file and decodes it to linear colours: PCX (the skins of MD2
// models) by RISE's own reader, PNG, JPEG, TGA, BMP, PNM and the others
// through stb_image, each decoded by `encoding` (sRGB for colours, linear for
// data such as normal maps); Radiance HDR and OpenEXR kept as their linear
// values. Files larger than kLargestImageFile are refused (file_limits.hpp),
// and so are headers that promise more than the file holds, more pixels than
// kMostImagePixels or more than the memory allows (image_headers.hpp).
// Throws ImageFileError naming the file and what failed. A file read with a fix (a PCX palette
// without its marker) adds a sentence saying so to `warnings`, when given.
Image readImage(const std::filesystem::path& path, Encoding encoding = Encoding::Srgb,
                std::vector<std::string>* warnings = nullptr);

}  // namespace rise
