#include "io/pcx_file.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/image_headers.hpp"

namespace rise {

namespace {

constexpr std::size_t kHeaderSize = 128;
constexpr std::size_t kPaletteSize = 1 + 3 * 256;  // a 0x0C marker, then the colours
constexpr std::uint8_t kPaletteMarker = 0x0C;
constexpr std::uint8_t kRunFlags = 0xC0;  // a byte with both top bits set starts a run

std::uint16_t littleEndian16(std::span<const std::uint8_t> bytes, std::size_t offset) {
  return static_cast<std::uint16_t>(bytes[offset] | (bytes[offset + 1] << 8));
}

ImageFileError pcxError(const std::string& name, const std::string& problem) {
  return ImageFileError(name + ": " + problem);
}

// The header's facts about the image.
struct PcxLayout {
  int width;
  int height;
  int planes;
  int bytesPerLine;  // per plane, even, at least width
};

PcxLayout readLayout(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() < kHeaderSize || bytes[0] != 0x0A)
    throw pcxError(name, "not a PCX image: it does not start with a PCX header");
  const int encoding = bytes[2];
  const int bitsPerPixel = bytes[3];
  const int planes = bytes[65];
  if (encoding != 1) throw pcxError(name, "unsupported PCX encoding " + std::to_string(encoding));
  if (bitsPerPixel != 8 || (planes != 1 && planes != 3))
    throw pcxError(name, "unsupported PCX image of " + std::to_string(planes) + " plane(s) of " +
                             std::to_string(bitsPerPixel) +
                             " bits; expected 8-bit paletted or 24-bit colour");
  const PcxLayout layout{littleEndian16(bytes, 8) - littleEndian16(bytes, 4) + 1,
                         littleEndian16(bytes, 10) - littleEndian16(bytes, 6) + 1, planes,
                         littleEndian16(bytes, 66)};
  // Lines are padded to an even length; more than twice the width is no
  // padding but a corrupt header.
  if (layout.width <= 0 || layout.height <= 0 || layout.bytesPerLine < layout.width ||
      layout.bytesPerLine > 2 * layout.width + 2)
    throw pcxError(name, "the PCX header is corrupt: its image is " + std::to_string(layout.width) +
                             " x " + std::to_string(layout.height) + " with lines of " +
                             std::to_string(layout.bytesPerLine) + " bytes");
  checkImageSize(layout.width, layout.height, name);
  return layout;
}

// The run-length decoded scan lines, each `planes` lines of bytesPerLine
// bytes. Runs may carry on from one line to the next, as some writers do.
std::vector<std::uint8_t> decodeRuns(std::span<const std::uint8_t> encoded, std::size_t decodedSize,
                                     const std::string& name) {
  // Two bytes give a run of at most 63: a longer image is cut short.
  constexpr std::size_t kLongestRunPerByte = 32;
  if (decodedSize > kLongestRunPerByte * encoded.size())
    throw pcxError(name, "the PCX image data is cut short");
  std::vector<std::uint8_t> decoded;
  decoded.reserve(decodedSize);
  std::size_t at = 0;
  while (decoded.size() < decodedSize) {
    if (at >= encoded.size()) throw pcxError(name, "the PCX image data is cut short");
    const std::uint8_t byte = encoded[at++];
    if ((byte & kRunFlags) != kRunFlags) {
      decoded.push_back(byte);
      continue;
    }
    if (at >= encoded.size()) throw pcxError(name, "the PCX image data is cut short");
    const std::size_t run = std::min<std::size_t>(byte & ~kRunFlags, decodedSize - decoded.size());
    decoded.insert(decoded.end(), run, encoded[at++]);
  }
  return decoded;
}

// Where the image data of an 8-bit image ends: at the 0x0C marker before
// its palette of 768 bytes, or, when a writer left the marker out (some
// Quake II skins), at the palette, said in a warning.
std::size_t imageDataEnd(std::span<const std::uint8_t> bytes, const std::string& name,
                         std::vector<std::string>* warnings) {
  if (bytes.size() >= kHeaderSize + kPaletteSize &&
      bytes[bytes.size() - kPaletteSize] == kPaletteMarker)
    return bytes.size() - kPaletteSize;
  if (bytes.size() < kHeaderSize + kPaletteSize - 1)
    throw pcxError(name, "the 8-bit PCX image has no 256-colour palette at its end");
  if (warnings)
    warnings->push_back(name +
                        ": the 8-bit PCX image's palette lacks its 0x0C marker byte; read the "
                        "last 768 bytes as the palette");
  return bytes.size() - kPaletteSize + 1;
}

}  // namespace

Image decodePcx(std::span<const std::uint8_t> bytes, const std::string& name, Encoding encoding,
                std::vector<std::string>* warnings) {
  const PcxLayout layout = readLayout(bytes, name);
  const bool paletted = layout.planes == 1;
  const std::size_t dataEnd = paletted ? imageDataEnd(bytes, name, warnings) : bytes.size();
  const std::size_t lineSize = static_cast<std::size_t>(layout.planes) * layout.bytesPerLine;
  const std::span<const std::uint8_t> encoded = bytes.subspan(kHeaderSize, dataEnd - kHeaderSize);
  const std::vector<std::uint8_t> lines = decodeRuns(encoded, lineSize * layout.height, name);
  const std::span<const std::uint8_t> palette = bytes.last(kPaletteSize - 1);

  const auto linear = [encoding](std::uint8_t byte) {
    const float value = static_cast<float>(byte) / 255.0f;
    return encoding == Encoding::Srgb ? linearFromSrgb(value) : value;
  };
  Image image(layout.width, layout.height);
  for (int y = 0; y < layout.height; ++y) {
    const std::uint8_t* line = lines.data() + y * lineSize;
    for (int x = 0; x < layout.width; ++x) {
      std::array<std::uint8_t, 3> rgb;
      for (int channel = 0; channel < 3; ++channel)
        rgb[channel] =
            paletted ? palette[3 * line[x] + channel] : line[channel * layout.bytesPerLine + x];
      image.at(x, y) = Color(linear(rgb[0]), linear(rgb[1]), linear(rgb[2]));
    }
  }
  return image;
}

Image readPcxFile(const std::filesystem::path& path, Encoding encoding,
                  std::vector<std::string>* warnings) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw pcxError(path.string(), "cannot read the file");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                        std::istreambuf_iterator<char>());
  if (file.bad()) throw pcxError(path.string(), "cannot read the file");
  return decodePcx(bytes, path.string(), encoding, warnings);
}

}  // namespace rise
