// Animated PNG (APNG: Mozilla, 2008; part of the PNG specification since
// its third edition, 2025): a film that every web browser plays, written
// without a video encoder. It is a PNG file whose image is the first frame,
// so a viewer that knows no animation still shows that; an acTL chunk says
// how many frames follow, each announced by an fcTL chunk (its size, place
// and time on screen) and carried by fdAT chunks, which are IDAT chunks with
// a sequence number in front.
//
// Frames already written as PNG files are joined without decoding them: each
// frame's compressed image data moves unchanged from its IDAT chunks into the
// film's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rise {

// One chunk of a PNG file: its four-letter type and its data.
struct PngChunk {
  std::string type;
  std::vector<std::uint8_t> data;
};

// The chunks of a PNG file's bytes, in order, each checked against its CRC.
// Throws ImageFileError naming `path` when the bytes are not a whole PNG file.
std::vector<PngChunk> pngChunks(const std::vector<std::uint8_t>& bytes,
                                const std::filesystem::path& path);

// The bytes of a PNG file made of these chunks: the signature, then each
// chunk with its length and CRC.
std::vector<std::uint8_t> pngFileOf(const std::vector<PngChunk>& chunks);

// Joins PNG files of one size and kind into an animated PNG at `film`,
// `framesPerSecond` frames a second, playing forever. The film is written
// whole or not at all. Throws ImageFileError naming a frame that cannot be
// read or differs from the first, OutputFileError when the film cannot be
// written.
void writeAnimatedPng(const std::vector<std::filesystem::path>& frames,
                      const std::filesystem::path& film, int framesPerSecond);

}  // namespace rise
