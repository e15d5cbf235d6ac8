// Inputs beyond what RISE reads: scene files, models and images that never
// end (/dev/zero), are too large, or promise more pixels than RISE decodes,
// are refused at once with the limit, and unreadable images are explained
// in the user's words with the decoder's after them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/file_limits.hpp"
#include "io/image_io.hpp"
#include "io/mesh_file.hpp"
#include "io/scene_file.hpp"
#include "support/png_header_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

template <typename Error, typename Load>
std::string errorOf(Load load) {
  try {
    load();
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(InputLimits, AStreamThatNeverEndsIsNotASceneFile) {
  EXPECT_EQ(errorOf<SceneError>([] { loadSceneFile("/dev/zero"); }),
            "/dev/zero: not a regular file (a device or a pipe); expected a file on disk");
  std::istringstream large(std::string(kLargestSceneFile + 1, '#'));
  EXPECT_EQ(errorOf<SceneError>([&] { loadSceneStream(large, "<stdin>"); }).substr(0, 45),
            "<stdin>: the scene file is larger than the 16");
}

TEST(InputLimits, ADeviceIsNotAModelOrAnImage) {
  const std::string notRegular = "not a regular file (a device or a pipe); expected a file on disk";
  EXPECT_EQ(errorOf<MeshFileError>([] { loadMeshFile("/dev/zero"); }), notRegular);
  EXPECT_EQ(errorOf<ImageFileError>([] { readImage("/dev/urandom"); }),
            "/dev/urandom: " + notRegular);
}

class ImageLimits : public TemporaryFolderTest {
 protected:
  fs::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(directory_ / name, std::ios::binary) << bytes;
    return directory_ / name;
  }
};

TEST_F(ImageLimits, AnImageOfMorePixelsThanRiseReadsIsRefusedBeforeItIsDecoded) {
  const fs::path huge = write("huge.png", pngHeader(10000, 10000));
  EXPECT_EQ(errorOf<ImageFileError>([&] { readImage(huge); }),
            huge.string() +
                ": the image is 10000 x 10000 pixels, more than the 33554432 (8192 x 4096) that "
                "RISE reads");
}

TEST_F(ImageLimits, AnUncompressedTgaCutShortIsRefusedBeforeItIsDecoded) {
  // The header of a grey image of 3000 x 2000 one-byte pixels, then 10 of them.
  const auto tga = [&](int width, int height, int pixels) {
    const std::string header{0,
                             0,
                             3,
                             0,
                             0,
                             0,
                             0,
                             0,
                             0,
                             0,
                             0,
                             0,
                             static_cast<char>(width & 0xff),
                             static_cast<char>(width >> 8),
                             static_cast<char>(height & 0xff),
                             static_cast<char>(height >> 8),
                             8,
                             0};
    return header + std::string(static_cast<std::size_t>(pixels), '\x80');
  };
  const fs::path cut = write("cut.tga", tga(3000, 2000, 10));
  EXPECT_EQ(errorOf<ImageFileError>([&] { readImage(cut); }),
            cut.string() +
                ": the file is cut short: its TGA header promises 3000 x 2000 pixels, "
                "6000018 bytes, but it has 28");
  // stb_image knows a TGA file by its header, whatever its name.
  EXPECT_THROW(readImage(write("cut.bmp", tga(3000, 2000, 10))), ImageFileError);
  const Image whole = readImage(write("whole.tga", tga(30, 20, 600)));
  EXPECT_EQ(whole.width(), 30);
  EXPECT_EQ(whole.height(), 20);
}

TEST_F(ImageLimits, ADecoderFailureIsSaidInTheUsersWords) {
  const fs::path cut = write("cut.png", pngHeader(4, 4));
  EXPECT_EQ(
      errorOf<ImageFileError>([&] { readImage(cut); }),
      cut.string() + ": the image data is corrupt or cut short (stb_image: unknown PNG chunk '')");
  const fs::path text = write("text.png", "not an image at all");
  EXPECT_EQ(errorOf<ImageFileError>([&] { readImage(text); }),
            text.string() +
                ": not an image in a format RISE reads (PNG, JPEG, TGA, BMP, GIF, PSD, PNM, HDR, "
                "PCX) (stb_image: unknown image type)");
}

}  // namespace
}  // namespace rise
