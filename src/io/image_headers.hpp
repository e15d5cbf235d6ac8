// What an image file's header promises, checked before the image is decoded.
// The decoders (stb_image, OpenEXR, RISE's PCX reader) take the memory of
// every pixel a header claims before they read one, and stb_image reads past
// the end of a short file as if its pixels were there: a file of a few bytes
// could claim an image of millions of pixels. So a header must give a size
// that an image can have, no more pixels than kMostImagePixels, a file of at
// least the bytes its pixels take in the format's most compact encoding, and
// a size whose decoding fits in the memory RISE may take.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace rise {

// The memory decoding takes a pixel: the image's linear colour, and at most
// as much again for the decoder's own buffers (stb_image's bytes, a PNG's
// inflated rows, OpenEXR's lines).
inline constexpr std::uint64_t kDecodingBytesPerPixel = 24;

// Throws ImageFileError when a size from a header is none that an image has,
// more pixels than RISE reads, or more than the memory allows to decode.
void checkImageSize(std::int64_t width, std::int64_t height, const std::filesystem::path& path);

// The checks for a file that stb_image decodes (PNG, JPEG, TGA, BMP, PNM,
// HDR and the others), its header read from `file`, which is put back where it
// was; the file's length checked against the least that the pixels of a PPM
// or PGM, a TGA or a Radiance HDR file take.
void checkStbImageHeader(std::FILE* file, const std::filesystem::path& path);

}  // namespace rise
