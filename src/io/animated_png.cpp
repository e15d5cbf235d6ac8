#include "io/animated_png.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <fstream>

#include "io/atomic_file.hpp"
#include "io/file_limits.hpp"
#include "io/image_io.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::uint8_t, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// The four bytes of a chunk's length, its type and its CRC.
constexpr std::size_t kChunkLength = 4;
constexpr std::size_t kChunkType = 4;
constexpr std::size_t kChunkCrc = 4;

ImageFileError frameError(const fs::path& path, const std::string& problem) {
  return ImageFileError(path.string() + ": " + problem);
}

std::uint32_t bigEndianAt(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
         std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
}

void appendBigEndian(std::vector<std::uint8_t>& bytes, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(std::uint8_t(value >> shift));
}

void appendBigEndian16(std::vector<std::uint8_t>& bytes, std::uint16_t value) {
  bytes.push_back(std::uint8_t(value >> 8));
  bytes.push_back(std::uint8_t(value));
}

// The CRC of a chunk covers its type and its data (zlib's crc32 is the CRC
// the PNG specification defines).
std::uint32_t chunkCrc(const std::uint8_t* typeAndData, std::size_t size) {
  return static_cast<std::uint32_t>(
      crc32(crc32(0L, Z_NULL, 0), typeAndData, static_cast<uInt>(size)));
}

std::vector<std::uint8_t> fileBytes(const fs::path& path) {
  if (const std::optional<std::string> problem = fileKindOrSizeProblem(path, kLargestImageFile))
    throw frameError(path, *problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw frameError(path, "cannot open the frame");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A frame's header and its compressed image data, all its IDAT chunks' data
// in order.
struct PngFrame {
  std::vector<std::uint8_t> header;
  std::vector<std::uint8_t> imageData;

  std::uint32_t width() const { return bigEndianAt(header, 0); }
  std::uint32_t height() const { return bigEndianAt(header, 4); }
};

PngFrame readFrame(const fs::path& path) {
  PngFrame frame;
  for (PngChunk& chunk : pngChunks(fileBytes(path), path)) {
    if (chunk.type == "IHDR") frame.header = std::move(chunk.data);
    if (chunk.type == "IDAT")
      frame.imageData.insert(frame.imageData.end(), chunk.data.begin(), chunk.data.end());
    if (chunk.type == "acTL") throw frameError(path, "the frame is itself an animation");
  }
  if (frame.header.size() != 13 || frame.imageData.empty())
    throw frameError(path, "not a PNG image: no header or no image data");
  return frame;
}

// The image data of one frame, cut into chunks no larger than a PNG
// encoder's usual ones, as a decoder streaming the film expects.
constexpr std::size_t kLargestDataChunk = 1 << 20;

class FilmWriter {
 public:
  explicit FilmWriter(std::vector<PngChunk>& chunks) : chunks_(chunks) {}

  void addFrame(const PngFrame& frame, int framesPerSecond, bool first) {
    chunks_.push_back({"fcTL", frameControl(frame, framesPerSecond)});
    for (std::size_t at = 0; at < frame.imageData.size(); at += kLargestDataChunk) {
      const auto begin = frame.imageData.begin() + static_cast<std::ptrdiff_t>(at);
      const auto end =
          frame.imageData.begin() +
          static_cast<std::ptrdiff_t>(std::min(frame.imageData.size(), at + kLargestDataChunk));
      // The first frame's data is the file's image, in IDAT chunks; the
      // others' go in fdAT chunks, which carry a sequence number first.
      PngChunk chunk{first ? "IDAT" : "fdAT", {}};
      chunk.data.reserve(4 + static_cast<std::size_t>(end - begin));
      if (!first) appendBigEndian(chunk.data, nextSequenceNumber_++);
      chunk.data.insert(chunk.data.end(), begin, end);
      chunks_.push_back(std::move(chunk));
    }
  }

 private:
  // Shown for 1/framesPerSecond of a second over the whole canvas, replacing
  // what was there (dispose and blend operations 0: none and source).
  std::vector<std::uint8_t> frameControl(const PngFrame& frame, int framesPerSecond) {
    std::vector<std::uint8_t> data;
    appendBigEndian(data, nextSequenceNumber_++);
    appendBigEndian(data, frame.width());
    appendBigEndian(data, frame.height());
    appendBigEndian(data, 0);  // x offset
    appendBigEndian(data, 0);  // y offset
    appendBigEndian16(data, 1);
    appendBigEndian16(data, static_cast<std::uint16_t>(framesPerSecond));
    data.push_back(0);
    data.push_back(0);
    return data;
  }

  std::vector<PngChunk>& chunks_;
  std::uint32_t nextSequenceNumber_ = 0;
};

}  // namespace

std::vector<PngChunk> pngChunks(const std::vector<std::uint8_t>& bytes, const fs::path& path) {
  if (bytes.size() < kPngSignature.size() ||
      !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin()))
    throw frameError(path, "not a PNG file (no PNG signature)");
  std::vector<PngChunk> chunks;
  std::size_t at = kPngSignature.size();
  while (chunks.empty() || chunks.back().type != "IEND") {
    if (bytes.size() - at < kChunkLength + kChunkType + kChunkCrc)
      throw frameError(path, "the PNG file is cut short (no IEND chunk)");
    const std::uint32_t length = bigEndianAt(bytes, at);
    if (length > bytes.size() - at - kChunkLength - kChunkType - kChunkCrc)
      throw frameError(path, "the PNG file is cut short inside a chunk");
    const std::uint8_t* typeAndData = bytes.data() + at + kChunkLength;
    if (chunkCrc(typeAndData, kChunkType + length) !=
        bigEndianAt(bytes, at + kChunkLength + kChunkType + length))
      throw frameError(path, "a PNG chunk's CRC does not match its bytes (a damaged file)");
    chunks.push_back({std::string(typeAndData, typeAndData + kChunkType),
                      {typeAndData + kChunkType, typeAndData + kChunkType + length}});
    at += kChunkLength + kChunkType + length + kChunkCrc;
  }
  return chunks;
}

std::vector<std::uint8_t> pngFileOf(const std::vector<PngChunk>& chunks) {
  std::vector<std::uint8_t> bytes(kPngSignature.begin(), kPngSignature.end());
  for (const PngChunk& chunk : chunks) {
    appendBigEndian(bytes, static_cast<std::uint32_t>(chunk.data.size()));
    const std::size_t typeAt = bytes.size();
    bytes.insert(bytes.end(), chunk.type.begin(), chunk.type.end());
    bytes.insert(bytes.end(), chunk.data.begin(), chunk.data.end());
    appendBigEndian(bytes, chunkCrc(bytes.data() + typeAt, bytes.size() - typeAt));
  }
  return bytes;
}

void writeAnimatedPng(const std::vector<fs::path>& frames, const fs::path& film,
                      int framesPerSecond) {
  if (frames.empty()) throw ImageFileError(film.string() + ": an animation needs frames");
  const PngFrame first = readFrame(frames.front());
  std::vector<PngChunk> chunks{{"IHDR", first.header}, {"acTL", {}}};
  appendBigEndian(chunks.back().data, static_cast<std::uint32_t>(frames.size()));
  appendBigEndian(chunks.back().data, 0);  // plays forever
  FilmWriter writer(chunks);
  writer.addFrame(first, framesPerSecond, true);
  for (std::size_t index = 1; index < frames.size(); ++index) {
    const PngFrame frame = readFrame(frames[index]);
    if (frame.header != first.header)
      throw frameError(frames[index],
                       "differs in size or kind from the first frame, " + frames.front().string());
    writer.addFrame(frame, framesPerSecond, false);
  }
  chunks.push_back({"IEND", {}});
  const std::vector<std::uint8_t> bytes = pngFileOf(chunks);
  AtomicFile file(film);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace rise
