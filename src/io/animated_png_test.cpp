#include "io/animated_png.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "io/image_io.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

std::uint32_t bigEndian(const std::vector<std::uint8_t>& data, std::size_t at) {
  return std::uint32_t{data[at]} << 24 | std::uint32_t{data[at + 1]} << 16 |
         std::uint32_t{data[at + 2]} << 8 | data[at + 3];
}

// A frame unlike the others: a gradient whose direction and colour turn
// with its number.
Image frameNumber(int number, int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) = Color(float((x + number * 7) % width) / float(width),
                             float((y * (number + 1)) % height) / float(height), 0.25f * number);
  return image;
}

class AnimatedPng : public TemporaryFolderTest {
 protected:
  std::vector<fs::path> writeFrames(int count, int width, int height) {
    std::vector<fs::path> frames;
    for (int number = 0; number < count; ++number) {
      frames.push_back(directory_ / ("frame_" + std::to_string(number) + ".png"));
      writeImage(frameNumber(number, width, height), frames.back());
    }
    return frames;
  }

  // Frame `number` of the film as a PNG file of its own: the film's header,
  // and the frame's data as IDAT chunks (an fdAT chunk's data less its
  // sequence number). A PNG decoder that knows nothing of animation reads it.
  fs::path extractFrame(const std::vector<PngChunk>& film, int number) {
    std::vector<PngChunk> still{film.front()};
    int frame = -1;
    for (const PngChunk& chunk : film) {
      if (chunk.type == "fcTL") ++frame;
      if (frame != number) continue;
      if (chunk.type == "IDAT") still.push_back(chunk);
      if (chunk.type == "fdAT")
        still.push_back({"IDAT", {chunk.data.begin() + 4, chunk.data.end()}});
    }
    still.push_back({"IEND", {}});
    const fs::path path = directory_ / ("extracted_" + std::to_string(number) + ".png");
    writeBytes(path, pngFileOf(still));
    return path;
  }
};

TEST_F(AnimatedPng, HoldsEveryFrameUnchangedInOrder) {
  const std::vector<fs::path> frames = writeFrames(3, 37, 23);
  const fs::path film = directory_ / "film.png";
  writeAnimatedPng(frames, film, 24);

  const std::vector<PngChunk> chunks = pngChunks(bytesOf(film), film);
  ASSERT_EQ(chunks[1].type, "acTL");
  EXPECT_EQ(bigEndian(chunks[1].data, 0), 3u);  // frames
  EXPECT_EQ(bigEndian(chunks[1].data, 4), 0u);  // plays forever
  // The film's own image is the first frame.
  const Image shown = readImage(film);
  for (int number = 0; number < 3; ++number) {
    const Image expected = readImage(frames[static_cast<std::size_t>(number)]);
    const Image extracted = readImage(extractFrame(chunks, number));
    ASSERT_EQ(extracted.width(), 37);
    ASSERT_EQ(extracted.height(), 23);
    for (int y = 0; y < 23; ++y)
      for (int x = 0; x < 37; ++x) {
        EXPECT_EQ(extracted.at(x, y), expected.at(x, y)) << "frame " << number;
        if (number == 0) {
          EXPECT_EQ(shown.at(x, y), expected.at(x, y));
        }
      }
  }
}

TEST_F(AnimatedPng, NumbersItsFrameChunksInOneSequenceAndTimesThem) {
  const fs::path film = directory_ / "film.png";
  writeAnimatedPng(writeFrames(4, 8, 5), film, 12);
  std::uint32_t expectedSequence = 0;
  int frameControls = 0;
  for (const PngChunk& chunk : pngChunks(bytesOf(film), film)) {
    if (chunk.type != "fcTL" && chunk.type != "fdAT") continue;
    EXPECT_EQ(bigEndian(chunk.data, 0), expectedSequence++) << chunk.type;
    if (chunk.type != "fcTL") continue;
    ++frameControls;
    ASSERT_EQ(chunk.data.size(), 26u);
    EXPECT_EQ(bigEndian(chunk.data, 4), 8u);             // width
    EXPECT_EQ(bigEndian(chunk.data, 8), 5u);             // height
    EXPECT_EQ(chunk.data[20] << 8 | chunk.data[21], 1);  // 1/12 of a second
    EXPECT_EQ(chunk.data[22] << 8 | chunk.data[23], 12);
  }
  EXPECT_EQ(frameControls, 4);
}

TEST_F(AnimatedPng, RefusesFramesOfAnotherSizeNamingThem) {
  std::vector<fs::path> frames = writeFrames(2, 8, 5);
  frames.push_back(directory_ / "wide.png");
  writeImage(frameNumber(2, 9, 5), frames.back());
  const fs::path film = directory_ / "film.png";
  try {
    writeAnimatedPng(frames, film, 24);
    FAIL() << "a frame of another size was joined";
  } catch (const ImageFileError& error) {
    EXPECT_NE(std::string(error.what()).find("wide.png: differs in size"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(film));
}

TEST_F(AnimatedPng, RefusesADamagedFrameNamingIt) {
  const std::vector<fs::path> frames = writeFrames(2, 8, 5);
  std::vector<std::uint8_t> bytes = bytesOf(frames[1]);
  bytes[bytes.size() / 2] ^= 0x40;
  writeBytes(frames[1], bytes);
  const fs::path film = directory_ / "film.png";
  try {
    writeAnimatedPng(frames, film, 24);
    FAIL() << "a damaged frame was joined";
  } catch (const ImageFileError& error) {
    EXPECT_NE(std::string(error.what()).find("frame_1.png: a PNG chunk's CRC"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(film));
}

}  // namespace
}  // namespace rise
