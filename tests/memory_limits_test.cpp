// Inputs that claim more memory than RISE may take, each refused before it is
// allocated, with a message naming what would take it and how to take less:
// a tessellation or shadow maps too fine for the scene, tiles whose places
// claim a huge image, image files whose headers promise more pixels than
// they hold or than the memory holds, and a depth sort that could not end in
// time. Run as bad input is (support/bad_input_testing.hpp), under an
// address-space limit of 512 MB.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "support/bad_input_testing.hpp"
#include "support/png_header_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

using bad_input_testing::BadInput;

const std::string kCamera = "camera: {position: [0, 0, -30], look_at: [0, 0, 0]}\n";

// `count` spheres side by side, all at one depth, lit by `lights` lights.
std::string spheres(int count, int lights) {
  std::string text = kCamera + "lights:\n";
  for (int i = 0; i < lights; ++i)
    text += "  - point: {position: [" + std::to_string(i) + ", 10, -10]}\n";
  text += "materials: {m: {}}\nobjects:\n";
  for (int i = 0; i < count; ++i)
    text += "  - sphere: {center: [" + std::to_string(i % 10 * 2 - 9) + ", " +
            std::to_string(i / 10 * 2 - 9) + ", 0], radius: 1, material: m}\n";
  return text;
}

std::string texturedBy(const std::string& image) {
  return kCamera + "materials: {m: {texture: {image: " + image +
         "}}}\nobjects: [sphere: {center: [0, 0, 0], radius: 1, material: m}]\n";
}

template <typename Value>
std::string bytesOf(Value value) {
  std::string bytes(sizeof value, '\0');
  std::memcpy(bytes.data(), &value, sizeof value);
  return bytes;
}

std::string exrAttribute(const std::string& name, const std::string& type,
                         const std::string& value) {
  return name + '\0' + type + '\0' + bytesOf(static_cast<std::int32_t>(value.size())) + value;
}

// The header of a ZIP-compressed OpenEXR file of width x height float RGB
// pixels, and its table of blocks (16 lines each), with no pixels after them.
std::string exrHeader(std::int32_t width, std::int32_t height) {
  std::string channels;
  for (const char* name : {"B", "G", "R"})
    channels += std::string(name) + '\0' + bytesOf(std::int32_t{2}) + std::string(4, '\0') +
                bytesOf(std::int32_t{1}) + bytesOf(std::int32_t{1});
  channels += '\0';
  const std::string box = bytesOf(std::int32_t{0}) + bytesOf(std::int32_t{0}) + bytesOf(width - 1) +
                          bytesOf(height - 1);
  const std::string header =
      std::string("\x76\x2f\x31\x01", 4) + bytesOf(std::int32_t{2}) +
      exrAttribute("channels", "chlist", channels) +
      exrAttribute("compression", "compression", std::string(1, '\x03')) +
      exrAttribute("dataWindow", "box2i", box) + exrAttribute("displayWindow", "box2i", box) +
      exrAttribute("lineOrder", "lineOrder", std::string(1, '\0')) +
      exrAttribute("pixelAspectRatio", "float", bytesOf(1.0f)) +
      exrAttribute("screenWindowCenter", "v2f", bytesOf(0.0f) + bytesOf(0.0f)) +
      exrAttribute("screenWindowWidth", "float", bytesOf(1.0f)) + '\0';
  return header + std::string(8 * static_cast<std::size_t>((height + 15) / 16), '\0');
}

// A run-length encoded true-colour TGA header (image type 10).
std::string rleTgaHeader(std::uint16_t width, std::uint16_t height) {
  return std::string("\0\0\x0a\0\0\0\0\0\0\0\0\0", 12) + bytesOf(width) + bytesOf(height) +
         std::string("\x18\0", 2);
}

std::string tilePlace(const std::string& imageWidth, const std::string& imageHeight) {
  return R"({"image": "t.exr", "x": 0, "y": 0, "width": 16, "height": 16, "image_width": )" +
         imageWidth + R"(, "image_height": )" + imageHeight + "}";
}

std::vector<BadInput> memoryClaims() {
  const std::vector<std::string> render = {"render", "DIR/s.yaml", "--width",
                                           "64",     "-o",         "DIR/out.png"};
  const auto with = [&](std::vector<std::string> more) {
    more.insert(more.begin(), render.begin(), render.end());
    return more;
  };
  return {
      {"tessellation_of_100_spheres",
       {{"s.yaml", spheres(100, 1)}},
       with({"-a", "z-buffer", "--tessellation", "256"}),
       "/dev/null",
       2,
       "most of it for the 104,857,600 triangles of --tessellation 256; expected a lower "
       "--tessellation"},
      {"shadow_maps_of_four_lights",
       {{"s.yaml", spheres(1, 4)}},
       with({"-a", "scanline", "--shadows", "map", "--shadow-map-size", "8192"}),
       "/dev/null",
       2,
       "most of it for the shadow maps of 4 lights, 8192 x 8192 texels each; expected smaller "
       "shadow maps (--shadow-map-size)"},
      {"depth_sort_of_overlapping_spheres",
       {{"s.yaml", spheres(100, 1)}},
       with({"-a", "depth-sort", "--tessellation", "24"}),
       "/dev/null",
       2,
       "pairs of them overlap); expected a scene it can order within that"},
      {"tile_place_of_2e31_pixels",
       {{"a.tile.json", tilePlace("65536", "32768")}},
       {"merge", "DIR/", "-o", "DIR/whole.png"},
       "/dev/null",
       2,
       "a.tile.json: 'image_width' is 65536; expected a whole number of pixels from 1 to 32768"},
      {"tile_place_of_a_negative_size",
       {{"a.tile.json", tilePlace("-2147483647", "-2147483647")}},
       {"merge", "DIR/", "-o", "DIR/whole.png"},
       "/dev/null",
       2,
       "'image_width' is -2147483647; expected a whole number of pixels from 1 to 32768"},
      {"tile_place_beyond_the_memory",
       {{"a.tile.json", tilePlace("32768", "32768")}},
       {"merge", "DIR/", "-o", "DIR/whole.png"},
       "/dev/null",
       2,
       "a.tile.json: the 32768x32768 image the pieces make would take about 13 GB"},
      {"exr_of_20000_by_15000_in_8_kb",
       {{"s.yaml", texturedBy("big.exr")}, {"big.exr", exrHeader(20000, 15000)}},
       render,
       "/dev/null",
       2,
       "big.exr: the image is 20000 x 15000 pixels, more than the 33554432 (8192 x 4096) that "
       "RISE reads"},
      {"exr_beyond_the_memory",
       {{"s.yaml", texturedBy("large.exr")}, {"large.exr", exrHeader(8192, 4096)}},
       render,
       "/dev/null",
       2,
       "large.exr: decoding its 8192 x 4096 pixels would take about 0.8 GB, more than the"},
      {"png_beyond_the_memory",
       {{"s.yaml", texturedBy("large.png")}, {"large.png", pngHeader(8192, 4096)}},
       render,
       "/dev/null",
       2,
       "large.png: decoding its 8192 x 4096 pixels would take about 0.8 GB"},
      {"ppm_cut_short",
       {{"s.yaml", texturedBy("cut.ppm")},
        {"cut.ppm", "P6\n4096 4096\n255\n" + std::string(1000, 'x')}},
       render,
       "/dev/null",
       2,
       "cut.ppm: the file is cut short: its PPM header promises 4096 x 4096 pixels, 50331665 "
       "bytes, but it has 1017"},
      {"ppm_of_a_size_past_the_numbers",
       {{"s.yaml", texturedBy("huge.ppm")}, {"huge.ppm", "P6\n99999999999 2147483649\n255\n"}},
       render,
       "/dev/null",
       2,
       "huge.ppm: the image is 99999999999 x 2147483649 pixels, more than the 33554432"},
      {"rle_tga_cut_short",
       {{"s.yaml", texturedBy("cut.tga")},
        {"cut.tga", rleTgaHeader(8192, 4096) + std::string(100, '\x80')}},
       render,
       "/dev/null",
       2,
       "cut.tga: the file is cut short: its TGA header promises 8192 x 4096 pixels, at least "
       "1048594 bytes, but it has 118"},
      {"hdr_cut_short",
       {{"s.yaml", texturedBy("cut.hdr")},
        {"cut.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4096 +X 4096\n" +
                        std::string("\x02\x02\x10\x00", 4) + std::string(100, '\0')}},
       render,
       "/dev/null",
       2,
       "cut.hdr: the file is cut short: its Radiance HDR header promises 4096 x 4096 pixels, at "
       "least 1097779 bytes, but it has 155"},
  };
}

class MemoryClaims : public TemporaryFolderTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(MemoryClaims, AreRefusedBeforeTheMemoryIsTaken) {
#ifdef RISE_SANITIZED_BUILD
  GTEST_SKIP() << "a sanitized build has no address-space limit to be refused within";
#endif
  bad_input_testing::expectRefusedAtOnce(GetParam(), directory_);
}

INSTANTIATE_TEST_SUITE_P(Resources, MemoryClaims, ::testing::ValuesIn(memoryClaims()),
                         bad_input_testing::nameOf);

}  // namespace
}  // namespace rise
