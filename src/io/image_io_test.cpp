#include "io/image_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

class ImageIoTest : public TemporaryFolderTest {
 protected:
  std::vector<std::string> filesInDirectory() const {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

std::string fileContents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The stored 8-bit values of an image file, as stb_image decodes them.
std::vector<int> storedBytes(const fs::path& path) {
  int width = 0;
  int height = 0;
  int channels = 0;
  stbi_uc* bytes = stbi_load(path.c_str(), &width, &height, &channels, 3);
  EXPECT_NE(bytes, nullptr) << path;
  if (bytes == nullptr) return {};
  std::vector<int> values(bytes, bytes + width * height * 3);
  stbi_image_free(bytes);
  return values;
}

// The message of the ImageFileError that `action` throws.
template <typename Action>
std::string imageFileErrorOf(Action action) {
  try {
    action();
  } catch (const ImageFileError& error) {
    return error.what();
  }
  return "no error";
}

TEST(Srgb, KnownValues) {
  EXPECT_FLOAT_EQ(srgbFromLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbFromLinear(1.0f), 1.0f);
  EXPECT_NEAR(srgbFromLinear(0.5f), 0.7354f, 1e-4f);
  EXPECT_FLOAT_EQ(srgbFromLinear(0.001f), 0.01292f);  // the linear segment near black
  EXPECT_FLOAT_EQ(linearFromSrgb(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(linearFromSrgb(1.0f), 1.0f);
  EXPECT_NEAR(linearFromSrgb(0.5f), 0.21404f, 1e-5f);
  EXPECT_FLOAT_EQ(linearFromSrgb(0.02f), 0.02f / 12.92f);
}

TEST(Srgb, DecodingInvertsEncoding) {
  for (int i = 0; i <= 1000; ++i) {
    const float linear = static_cast<float>(i) / 1000.0f;
    EXPECT_NEAR(linearFromSrgb(srgbFromLinear(linear)), linear, 1e-6f) << linear;
  }
}

// PNG and PPM store the same 8-bit levels: both must give back exactly the
// level each pixel was written with.
class EightBitRoundTrip : public ImageIoTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(EightBitRoundTrip, KeepsEveryLevelExactly) {
  const std::vector<int> levels = {0,   1,   10,  11,  12, 50, 100, 128, 187,
                                   188, 200, 254, 255, 3,  77, 160, 31,  240};
  Image image(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int channel = 0; channel < 3; ++channel)
        image.at(x, y)[channel] = linearFromSrgb(levels[(y * 3 + x) * 3 + channel] / 255.0f);
  const fs::path path = directory_ / (std::string("round-trip.") + GetParam());

  writeImage(image, path);

  EXPECT_EQ(storedBytes(path), levels);
  const Image read = readImage(path);
  ASSERT_EQ(read.width(), 3);
  ASSERT_EQ(read.height(), 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_EQ(read.at(x, y), image.at(x, y)) << x << "," << y;
}

TEST_P(EightBitRoundTrip, ClampsAndRoundsToNearest) {
  Image image(2, 1);
  image.at(0, 0) = Color(-0.5f, 2.0f, 0.21f);  // 0.21 * 255 = 53.55
  image.at(1, 0) = Color(0.5f, 0.2f, 0.001f);  // sRGB 187.52, 123.55, 3.29
  const fs::path linear = directory_ / (std::string("linear.") + GetParam());
  const fs::path srgb = directory_ / (std::string("srgb.") + GetParam());

  writeImage(image, linear, Encoding::Linear);
  writeImage(image, srgb, Encoding::Srgb);

  EXPECT_EQ(storedBytes(linear), (std::vector<int>{0, 255, 54, 128, 51, 0}));
  EXPECT_EQ(storedBytes(srgb), (std::vector<int>{0, 255, 126, 188, 124, 3}));
  EXPECT_EQ(readImage(linear, Encoding::Linear).at(0, 0), Color(0.0f, 1.0f, 54.0f / 255.0f));
}

INSTANTIATE_TEST_SUITE_P(ImageIo, EightBitRoundTrip, ::testing::Values("png", "ppm"));

TEST_F(ImageIoTest, PpmIsBinaryP6) {
  Image image(2, 1);
  image.at(0, 0) = Color(1.0f, 0.0f, 0.2f);
  image.at(1, 0) = Color(0.0f, 1.0f, 1.0f);
  const fs::path path = directory_ / "tiny.ppm";

  writeImage(image, path, Encoding::Linear);

  EXPECT_EQ(fileContents(path), std::string("P6\n2 1\n255\n\xff\x00\x33\x00\xff\xff", 17));
}

TEST_F(ImageIoTest, ExrKeepsLinearFloatsBeyondOne) {
  Image image(2, 2);
  image.at(0, 0) = Color(2.5f, 1000.0f, 0.0f);
  image.at(1, 0) = Color(-0.25f, 0.123456789f, 1.0f);
  image.at(0, 1) = Color(1e-6f, 7.0f, 3.14159265f);
  image.at(1, 1) = Color(0.5f, 0.5f, 65504.5f);
  const fs::path path = directory_ / "linear.exr";

  writeImage(image, path);  // the sRGB default does not apply to OpenEXR

  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  ASSERT_EQ(window.max.x - window.min.x + 1, 2);
  ASSERT_EQ(window.max.y - window.min.y + 1, 2);
  for (const char* channel : {"R", "G", "B"}) {
    const Imf::Channel* stored = file.header().channels().findChannel(channel);
    ASSERT_NE(stored, nullptr) << channel;
    EXPECT_EQ(stored->type, Imf::FLOAT) << channel;
  }
  Pixels read(4);
  Imf::FrameBuffer frameBuffer;
  char* base = reinterpret_cast<char*>(read.data());
  frameBuffer.insert("R", Imf::Slice(Imf::FLOAT, base, sizeof(Color), 2 * sizeof(Color)));
  frameBuffer.insert("G", Imf::Slice(Imf::FLOAT, base + 4, sizeof(Color), 2 * sizeof(Color)));
  frameBuffer.insert("B", Imf::Slice(Imf::FLOAT, base + 8, sizeof(Color), 2 * sizeof(Color)));
  file.setFrameBuffer(frameBuffer);
  file.readPixels(window.min.y, window.max.y);
  EXPECT_EQ(read, image.pixels());
  EXPECT_EQ(readImage(path).pixels(), image.pixels());  // and RISE reads them back unchanged
}

TEST_F(ImageIoTest, WriteIntoMissingDirectoryThrowsAndLeavesNothing) {
  const fs::path path = directory_ / "missing" / "x.png";

  EXPECT_EQ(imageFileErrorOf([&] { writeImage(Image(2, 2), path); }),
            path.string() + ": cannot write (No such file or directory)");
  EXPECT_FALSE(fs::exists(directory_ / "missing"));
  EXPECT_TRUE(filesInDirectory().empty());
}

TEST_F(ImageIoTest, FailedRenameRemovesTheTemporaryFile) {
  const fs::path path = directory_ / "taken.png";
  fs::create_directory(path);  // a directory cannot be replaced by a file

  EXPECT_THROW(writeImage(Image(2, 2), path), ImageFileError);
  EXPECT_EQ(filesInDirectory(), std::vector<std::string>{"taken.png"});
}

TEST_F(ImageIoTest, ReplacesAnExistingFileAndLeavesOnlyIt) {
  const fs::path path = directory_ / "again.ppm";
  writeImage(Image(1, 1, Color(1.0f)), path, Encoding::Linear);

  writeImage(Image(1, 1, Color(0.0f)), path, Encoding::Linear);

  EXPECT_EQ(storedBytes(path), (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(filesInDirectory(), std::vector<std::string>{"again.ppm"});
}

TEST_F(ImageIoTest, UnsupportedExtensionThrows) {
  EXPECT_EQ(imageFileErrorOf([] { writeImage(Image(2, 2), "out.jpg"); }),
            "out.jpg: unsupported image format '.jpg' (use .png, .ppm or .exr)");
}

TEST_F(ImageIoTest, ReadingAMissingFileThrowsNamingIt) {
  const fs::path path = directory_ / "absent.png";
  EXPECT_EQ(imageFileErrorOf([&] { readImage(path); }),
            path.string() + ": cannot read (No such file or directory)");
}

}  // namespace
}  // namespace rise
