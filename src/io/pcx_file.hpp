// ZSoft PCX images, the format of Quake II model skins: a 128-byte header,
// then the scan lines, run-length encoded, then for 8-bit images a palette
// of 256 RGB colours. Read are the 8-bit paletted images (one plane) and the
// 24-bit ones (three planes of R, G and B per line), which cover what paint
// programs and Quake's tools wrote.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "io/image_io.hpp"

namespace rise {

// Decodes a PCX file held in memory; `name` names it in errors. Throws
// ImageFileError for anything that is not a PCX image of a supported kind,
// is larger than kMostImagePixels, or is cut short. An 8-bit image whose
// palette lacks its marker byte is read, with a warning added to `warnings`
// when given.
Image decodePcx(std::span<const std::uint8_t> bytes, const std::string& name,
                Encoding encoding = Encoding::Srgb, std::vector<std::string>* warnings = nullptr);

// Reads and decodes a PCX file. Throws ImageFileError naming the path.
Image readPcxFile(const std::filesystem::path& path, Encoding encoding = Encoding::Srgb,
                  std::vector<std::string>* warnings = nullptr);

}  // namespace rise
