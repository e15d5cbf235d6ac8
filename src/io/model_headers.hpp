// The headers of model files, checked against the files before Assimp reads
// them: a header that promises more than its file holds (a PLY file of
// 2e9 faces in 36 bytes, an MD2 model of 0 vertices) would make Assimp ask
// for gigabytes, read past its buffers or crash. Each check throws
// MeshFileError saying which promise the file breaks.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rise {

// The 17 little-endian integers that open a Quake II model: its ident
// "IDP2" and version 8, then the skin's size, a keyframe's size, the count
// of each part and where each part starts.
struct Md2Header {
  struct Part {
    std::int64_t count = 0;
    std::int64_t offset = 0;
  };
  std::int64_t skinWidth = 0;
  std::int64_t skinHeight = 0;
  std::int64_t frameSize = 0;
  Part skins, texCoords, triangles, glCommands, frames;
  std::int64_t vertices = 0;  // in each keyframe
  std::int64_t end = 0;       // where the header says the file ends
};

inline constexpr std::size_t kMd2HeaderSize = 68;

// The header of the MD2 model held in `file`, each field checked against the
// file: a keyframe's size against its vertices, every part inside the file,
// every triangle's indices in range and every skin name ended.
Md2Header checkedMd2Header(std::span<const std::uint8_t> file);

// The skin names of a checked MD2 model.
std::vector<std::string> md2SkinNames(const Md2Header& header, std::span<const std::uint8_t> file);

// Checks the header of a PLY file, given its start (at least the header) and
// its size: the header must end, and its elements fit in what follows it.
void checkPlyHeader(std::string_view start, std::uintmax_t fileSize);

// Checks the counts of an OFF file's vertices and faces against its size.
void checkOffHeader(std::string_view start, std::uintmax_t fileSize);

}  // namespace rise
