// Textures looked up: image textures and their filters and mipmaps, moved
// texture coordinates, the PCX skins of MD2 models, Perlin's noise and the
// solid textures made of it, and bump and normal maps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "io/mesh_file.hpp"
#include "io/pcx_file.hpp"
#include "scene/textures/bump_map.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/noise_texture.hpp"
#include "scene/textures/normal_map.hpp"
#include "scene/textures/perlin_noise.hpp"
#include "scene/textures/transformed_texture.hpp"
#include "shading/bump_mapping.hpp"
#include "shading/material_at_point.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::expectColor;

constexpr float kTolerance = 1e-4f;

// A 2 x 2 image: red, green on top; blue, white below.
std::shared_ptr<const Image> fourTexels() {
  auto image = std::make_shared<Image>(2, 2);
  image->at(0, 0) = Color(1, 0, 0);
  image->at(1, 0) = Color(0, 1, 0);
  image->at(0, 1) = Color(0, 0, 1);
  image->at(1, 1) = Color(1, 1, 1);
  return image;
}

TEST(ImageTexture, NearestTakesTheTexelUnderThePointWithVUpAndRepeats) {
  const ImageTexture texture(fourTexels(), TextureFilter::Nearest);
  expectColor(texture.colorAtUv({0.25f, 0.75f}), Color(1, 0, 0));
  expectColor(texture.colorAtUv({0.75f, 0.75f}), Color(0, 1, 0));
  expectColor(texture.colorAtUv({0.25f, 0.25f}), Color(0, 0, 1));
  expectColor(texture.colorAtUv({1.75f, -0.75f}), Color(1, 1, 1));
}

TEST(ImageTexture, BilinearIsExactAtTexelCentresAndBlendsBetween) {
  const ImageTexture texture(fourTexels(), TextureFilter::Bilinear);
  expectColor(texture.colorAtUv({0.25f, 0.75f}), Color(1, 0, 0));
  expectColor(texture.colorAtUv({0.5f, 0.75f}), Color(0.5f, 0.5f, 0));
  expectColor(texture.colorAtUv({0.5f, 0.5f}), Color(0.5f, 0.5f, 0.5f));
  // Across the edge, the texels of the other side (the texture repeats).
  expectColor(texture.colorAtUv({0.0f, 0.75f}), Color(0.5f, 0.5f, 0));
}

TEST(ImageTexture, MipmapLevelsAverageTheTexelsTheyCover) {
  // A 4 x 4 board of single-texel squares: every coarser level is grey.
  auto board = std::make_shared<Image>(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) board->at(x, y) = Color((x + y) % 2 == 0 ? 1.0f : 0.0f);
  const ImageTexture texture(board, TextureFilter::Trilinear);
  ASSERT_EQ(texture.mipmap()->levels().size(), 3u);
  EXPECT_EQ(texture.mipmap()->levels()[1].width(), 2);
  EXPECT_EQ(texture.mipmap()->levels()[2].width(), 1);
  expectColor(texture.mipmap()->levels()[2].at(0, 0), Color(0.5f));
  // A footprint of one texel reads level 0; of two, level 1; between, a blend.
  const Vec2 centreOfTexel(0.125f, 1.0f - 0.125f);
  const auto footprint = [](float width) {
    return PixelFootprint{Vec2(width, 0.0f), Vec2(0.0f, width)};
  };
  expectColor(texture.colorAtUv(centreOfTexel, footprint(0.25f)), Color(1.0f));
  expectColor(texture.colorAtUv(centreOfTexel, footprint(0.5f)), Color(0.5f));
  expectColor(texture.colorAtUv(centreOfTexel, footprint(0.25f * std::sqrt(2.0f))), Color(0.75f));
  // Without a footprint (the ray tracers), level 0.
  expectColor(texture.colorAtUv(centreOfTexel), Color(1.0f));
}

TEST(TransformedTexture, ScalesRotatesAndOffsetsTheCoordinates) {
  UvTransform transform;
  transform.scale = Vec2(2.0f, 3.0f);
  transform.rotateDegrees = 90.0f;
  transform.offset = Vec2(0.5f, 0.0f);
  const Vec2 moved = transform.apply({1.0f, 1.0f});
  EXPECT_NEAR(moved.x, -3.0f + 0.5f, kTolerance);
  EXPECT_NEAR(moved.y, 2.0f, kTolerance);
}

const std::filesystem::path kSydney =
    std::filesystem::path(RISE_SOURCE_DIR) / "examples/models/sydney";

TEST(PcxFile, SydneysSkinMatchesTheSameImageAsBmp) {
  const Image pcx = readImage(kSydney / "sydney.pcx");
  const Image bmp = readImage(kSydney / "sydney.bmp");
  ASSERT_EQ(pcx.width(), 308);
  ASSERT_EQ(pcx.height(), 193);
  ASSERT_EQ(bmp.width(), pcx.width());
  ASSERT_EQ(bmp.height(), pcx.height());
  int differing = 0;
  for (int y = 0; y < pcx.height(); ++y)
    for (int x = 0; x < pcx.width(); ++x) differing += pcx.at(x, y) != bmp.at(x, y) ? 1 : 0;
  EXPECT_EQ(differing, 0);
}

std::vector<std::uint8_t> pcxHeader(int width, int height, int planes) {
  std::vector<std::uint8_t> bytes(128, 0);
  bytes[0] = 0x0A;
  bytes[1] = 5;
  bytes[2] = 1;
  bytes[3] = 8;
  bytes[8] = static_cast<std::uint8_t>(width - 1);
  bytes[10] = static_cast<std::uint8_t>(height - 1);
  bytes[65] = static_cast<std::uint8_t>(planes);
  bytes[66] = static_cast<std::uint8_t>(width + width % 2);
  return bytes;
}

TEST(PcxFile, DecodesRunsAndThePalette) {
  std::vector<std::uint8_t> bytes = pcxHeader(3, 1, 1);
  // A run of two of index 1, a literal 2, and the line's padding byte.
  for (std::uint8_t byte : {0xC2, 0x01, 0x02, 0x00}) bytes.push_back(byte);
  bytes.push_back(0x0C);
  std::vector<std::uint8_t> palette(768, 0);
  palette[3] = 255;          // index 1: red
  palette[3 * 2 + 2] = 255;  // index 2: blue
  bytes.insert(bytes.end(), palette.begin(), palette.end());
  const Image image = decodePcx(bytes, "test.pcx");
  ASSERT_EQ(image.width(), 3);
  expectColor(image.at(0, 0), Color(1, 0, 0));
  expectColor(image.at(1, 0), Color(1, 0, 0));
  expectColor(image.at(2, 0), Color(0, 0, 1));
}

TEST(PcxFile, ReadsAPaletteWithoutItsMarkerAndWarns) {
  std::vector<std::uint8_t> bytes = pcxHeader(3, 1, 1);
  for (std::uint8_t byte : {0xC2, 0x01, 0x02, 0x00}) bytes.push_back(byte);
  std::vector<std::uint8_t> palette(768, 0);
  palette[3] = 255;  // index 1: red
  bytes.insert(bytes.end(), palette.begin(), palette.end());
  std::vector<std::string> warnings;
  const Image image = decodePcx(bytes, "skin.pcx", Encoding::Srgb, &warnings);
  expectColor(image.at(0, 0), Color(1, 0, 0));
  EXPECT_EQ(warnings, std::vector<std::string>{
                          "skin.pcx: the 8-bit PCX image's palette lacks its 0x0C marker byte; "
                          "read the last 768 bytes as the palette"});
  bytes.resize(bytes.size() - 2);  // now the palette is not there in full
  EXPECT_THROW(decodePcx(bytes, "skin.pcx"), ImageFileError);
}

TEST(PcxFile, RefusesAHeaderOfMoreThanTheFileCanHold) {
  std::vector<std::uint8_t> bytes = pcxHeader(200, 200, 3);
  bytes.resize(200);
  EXPECT_THROW(decodePcx(bytes, "short.pcx"), ImageFileError);
  bytes = pcxHeader(200, 200, 1);
  bytes[66] = 0xff;  // lines of 65535 bytes for 200 pixels
  bytes[67] = 0xff;
  bytes.resize(128 + 769, 0x0C);
  try {
    decodePcx(bytes, "wide.pcx");
    FAIL() << "no error";
  } catch (const ImageFileError& error) {
    EXPECT_EQ(std::string(error.what()),
              "wide.pcx: the PCX header is corrupt: its image is 200 x 200 with lines of 65535 "
              "bytes");
  }
}

TEST(PcxFile, ReportsAnImageCutShort) {
  std::vector<std::uint8_t> bytes = pcxHeader(4, 4, 3);
  bytes.push_back(0x05);
  try {
    decodePcx(bytes, "short.pcx");
    FAIL() << "no error";
  } catch (const ImageFileError& error) {
    EXPECT_EQ(std::string(error.what()), "short.pcx: the PCX image data is cut short");
  }
}

TEST(PerlinNoise, VanishesAtTheLatticeAndMatchesPerlinsReference) {
  EXPECT_EQ(perlinNoise(Vec3(3, 42, 7)), 0.0f);
  EXPECT_EQ(perlinNoise(Vec3(-5, 0, 12)), 0.0f);
  // The value Perlin's Java reference gives at (3.14, 42, 7).
  EXPECT_NEAR(perlinNoise(Vec3(3.14f, 42.0f, 7.0f)), 0.13691995878400012f, 1e-4f);
  // Continuous: close points, close values.
  EXPECT_NEAR(perlinNoise(Vec3(0.5f, 0.5f, 0.5f)), perlinNoise(Vec3(0.5001f, 0.5f, 0.5f)), 1e-3f);
}

TEST(NoiseTexture, WoodRingsRepeatAlongTheRadius) {
  const NoiseTexture wood(NoisePattern::Wood, Color(0.0f), Color(1.0f), 1.0f);
  // On the lattice the noise is zero: the rings are exactly 1/4 unit apart.
  EXPECT_NEAR(wood.mixAt(Vec3(1, 0, 0)), 0.0f, kTolerance);
  EXPECT_NEAR(wood.mixAt(Vec3(0, 3, 2)), 0.0f, kTolerance);
  for (const NoisePattern pattern : {NoisePattern::Perlin, NoisePattern::Marble}) {
    const NoiseTexture texture(pattern, Color(0.0f), Color(1.0f), 3.0f);
    for (float x = 0.0f; x < 2.0f; x += 0.13f) {
      const float mix = texture.mixAt(Vec3(x, 0.3f, 0.7f));
      EXPECT_GE(mix, 0.0f);
      EXPECT_LE(mix, 1.0f);
    }
  }
}

TEST(Md2Skin, IsTheSkinNamedLikeTheModelOrTheFoldersOnlyPcx) {
  const std::filesystem::path models = std::filesystem::path(RISE_SOURCE_DIR) / "examples/models";
  EXPECT_EQ(findMd2Skin(models / "sydney/sydney.md2"), models / "sydney/sydney.pcx");
  EXPECT_EQ(findMd2Skin(models / "ratamahatta/tris.md2"), models / "ratamahatta/Ratamahatta.pcx");
  EXPECT_EQ(findMd2Skin(models / "spot/spot.md2"), std::nullopt);
}

// A height that rises along u: `slope` per unit of u.
class Ramp final : public Texture {
 public:
  explicit Ramp(float slope) : slope_(slope) {}
  Color colorAt(const SurfacePoint& surface) const override { return Color(slope_ * surface.uv.x); }

 private:
  float slope_;
};

TEST(BumpMap, TiltsThePlanesNormalAgainstTheSlope) {
  // The plane y = 0 has u = x and v = -z; a height rising by 0.5 per unit of
  // x tilts its normal back towards -x: (-0.5, 1, 0), normalised.
  SurfacePoint surface(Vec3(0.3f, 0.0f, 0.2f), Vec3(0, 1, 0), Vec2(0.3f, -0.2f));
  surface.dpdu = Vec3(1, 0, 0);
  surface.dpdv = Vec3(0, 0, -1);
  const BumpMap bump(std::make_shared<Ramp>(0.25f), 2.0f, Vec2(1e-3f));
  EXPECT_TRUE(
      shape_testing::nearlyEqual(bumped(bump, surface), glm::normalize(Vec3(-0.5f, 1.0f, 0.0f))));
  // Texture coordinates stretched twice as far: half the slope in space.
  surface.dpdu = Vec3(2, 0, 0);
  EXPECT_TRUE(
      shape_testing::nearlyEqual(bumped(bump, surface), glm::normalize(Vec3(-0.25f, 1.0f, 0.0f))));
}

// One colour everywhere.
class Uniform final : public Texture {
 public:
  explicit Uniform(Color color) : color_(color) {}
  Color colorAt(const SurfacePoint&) const override { return color_; }

 private:
  Color color_;
};

TEST(NormalMap, ReadsTheNormalInTheTangentFrame) {
  // The plane y = 0 seen from above, u = x and v = -z.
  SurfacePoint surface(Vec3(0.0f), Vec3(0, 1, 0), Vec2(0.0f));
  surface.dpdu = Vec3(2, 0, 0);
  surface.dpdv = Vec3(0, 0, -1);
  const auto normalFor = [&](const Color& color) {
    return normalMapped(NormalMap(std::make_shared<Uniform>(color)), surface);
  };
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(0.5f, 0.5f, 1.0f)), Vec3(0, 1, 0)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(1.0f, 0.5f, 0.5f)), Vec3(1, 0, 0)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(0.5f, 1.0f, 0.5f)), Vec3(0, 0, -1)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(1.0f, 0.5f, 1.0f)),
                                         glm::normalize(Vec3(1, 1, 0))));
}

}  // namespace
}  // namespace rise
