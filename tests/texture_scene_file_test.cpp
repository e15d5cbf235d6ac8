// The `texture`, `bump` and `normal_map` keys of the scene file: images found
// from the scene's folder, procedural textures, the errors for what is
// missing or wrong; mipmaps against aliasing; and MD2 models dressed in their
// skins.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/image_io.hpp"
#include "io/pcx_file.hpp"
#include "io/scene_error.hpp"
#include "io/scene_file.hpp"
#include "scene/scene.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/normal_map.hpp"
#include "scene/textures/perlin_noise.hpp"
#include "shading/bump_mapping.hpp"
#include "shading/material_at_point.hpp"
#include "support/raster_testing.hpp"
#include "support/shape_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

using shape_testing::expectColor;

const std::filesystem::path kSydney =
    std::filesystem::path(RISE_SOURCE_DIR) / "examples/models/sydney";

class TextureSceneFile : public TemporaryFolderTest {
 protected:
  void SetUp() override {
    TemporaryFolderTest::SetUp();
    std::filesystem::create_directories(directory_ / "textures");
    writeImage(Image(4, 2, Color(1.0f, 0.0f, 0.0f)), directory_ / "textures/red.png");
  }

  Scene load(const std::string& texture) {
    const std::filesystem::path path = directory_ / "scene.yaml";
    std::ofstream(path) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 40}\n"
                           "materials:\n  textured: {texture: "
                        << texture
                        << "}\n"
                           "objects:\n  - sphere: {center: [0, 0, 0], radius: 1, material: "
                           "textured}\n";
    return loadSceneFile(path);
  }

  std::string errorOf(const std::string& texture) {
    try {
      load(texture);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "no error";
  }
};

TEST_F(TextureSceneFile, ReadsAnImageRelativeToTheSceneFile) {
  const Scene scene = load("{image: textures/red.png, filter: nearest, scale: 2, rotate: 30}");
  ASSERT_TRUE(scene.materials[0].texture);
  SurfacePoint point(Vec3(0.0f), Vec3(0, 0, -1), Vec2(0.3f, 0.6f));
  expectColor(surfaceColors(scene.materials[0], point).color, Color(1, 0, 0));
}

TEST_F(TextureSceneFile, ReadsTheProceduralTextures) {
  for (const std::string kind : {"perlin", "marble", "wood"}) {
    const Scene scene = load("{" + kind + ": {colors: [[0, 0, 0], [1, 1, 1]], scale: 2}}");
    EXPECT_TRUE(scene.materials[0].texture) << kind;
  }
  const Scene checker = load("{checker: {colors: [[0, 0, 0], [1, 1, 1]], size: 0.5}}");
  SurfacePoint point(Vec3(0.0f), Vec3(0, 0, -1), Vec2(0.75f, 0.25f));
  expectColor(surfaceColors(checker.materials[0], point).color, Color(1, 1, 1));
}

TEST_F(TextureSceneFile, ReadsANormalMapLinearly) {
  // sRGB would decode the stored 188 to 0.5; read linearly it is 188 / 255.
  writeImage(Image(2, 2, Color(0.5f, 0.5f, 1.0f)), directory_ / "textures/flat.png");
  const std::filesystem::path path = directory_ / "normal.yaml";
  std::ofstream(path) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 40}\n"
                         "materials:\n  tiled: {normal_map: {image: textures/flat.png}}\n"
                         "objects:\n  - plane: {point: [0, 0, 0], normal: [0, 1, 0], material: "
                         "tiled}\n";
  const Scene scene = loadSceneFile(path);
  ASSERT_TRUE(scene.materials[0].normalMap);
  SurfacePoint surface(Vec3(0.0f), Vec3(0, 1, 0), Vec2(0.5f));
  surface.dpdu = Vec3(1, 0, 0);
  surface.dpdv = Vec3(0, 0, -1);
  const float stored = 2.0f * 188.0f / 255.0f - 1.0f;
  EXPECT_TRUE(shape_testing::nearlyEqual(shadingNormal(scene.materials[0], surface),
                                         glm::normalize(Vec3(stored, 1.0f, -stored)), 1e-3f));
}

TEST_F(TextureSceneFile, NamesAMissingImageAndWhatFailed) {
  const std::string error = errorOf("{image: textures/missing.png}");
  EXPECT_NE(error.find("scene.yaml:3:"), std::string::npos) << error;
  EXPECT_NE(error.find("cannot load texture image 'textures/missing.png'"), std::string::npos)
      << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

TEST_F(TextureSceneFile, NamesAnUnreadableImage) {
  std::ofstream(directory_ / "textures/broken.png") << "not a png";
  const std::string error = errorOf("{image: textures/broken.png}");
  EXPECT_NE(error.find("cannot load texture image 'textures/broken.png'"), std::string::npos)
      << error;
}

TEST_F(TextureSceneFile, RejectsTwoKindsAndImageKeysOnOtherKinds) {
  EXPECT_NE(errorOf("{image: textures/red.png, checker: {colors: [[0, 0, 0], [1, 1, 1]]}}")
                .find("texture needs exactly one of"),
            std::string::npos);
  EXPECT_NE(errorOf("{filter: nearest, wood: {colors: [[0, 0, 0], [1, 1, 1]]}}")
                .find("belongs to an image texture"),
            std::string::npos);
  EXPECT_NE(errorOf("{image: textures/red.png, filter: anisotropic}").find("'anisotropic'"),
            std::string::npos);
}

// A checker image on a floor receding to the horizon, drawn by the z-buffer
// at width x height.
Image recedingFloor(const std::filesystem::path& directory, const std::string& filter, int width,
                    int height) {
  const std::filesystem::path path = directory / ("floor-" + filter + ".yaml");
  std::ofstream(path)
      << "image: {width: " << width << ", height: " << height
      << "}\ncamera: {position: [0, 1, -4], look_at: [0, 0.2, 10], fov: 45}\n"
         "ambient: [1, 1, 1]\n"
         "materials:\n  floor: {ka: 1, kd: 0, texture: {image: textures/checker.png, filter: "
      << filter
      << ", scale: 8}}\n"
         "objects:\n  - polygon: {vertices: [[-8, 0, -4], [8, 0, -4], [8, 0, 60], [-8, 0, "
         "60]], material: floor}\n";
  const Scene scene = loadSceneFile(path);
  return raster_testing::render("z-buffer", scene).image;
}

// The mean over each factor x factor block of pixels.
Image downsampled(const Image& image, int factor) {
  Image small(image.width() / factor, image.height() / factor);
  for (int y = 0; y < small.height(); ++y)
    for (int x = 0; x < small.width(); ++x) {
      Color sum(0.0f);
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) sum += image.at(factor * x + dx, factor * y + dy);
      small.at(x, y) = sum / static_cast<float>(factor * factor);
    }
  return small;
}

float rootMeanSquareDifference(const Image& a, const Image& b) {
  float sum = 0.0f;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Color d = a.at(x, y) - b.at(x, y);
      sum += glm::dot(d, d);
    }
  return std::sqrt(sum / static_cast<float>(a.width() * a.height()));
}

TEST_F(TextureSceneFile, MipmappingReducesAliasingOnARecedingChecker) {
  Image board(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) board.at(x, y) = Color((x / 8 + y / 8) % 2 == 0 ? 1.0f : 0.0f);
  writeImage(board, directory_ / "textures/checker.png");
  constexpr int kWidth = 80, kHeight = 60, kSupersampling = 8;
  const Image reference = downsampled(
      recedingFloor(directory_, "bilinear", kSupersampling * kWidth, kSupersampling * kHeight),
      kSupersampling);
  const float bilinearError =
      rootMeanSquareDifference(recedingFloor(directory_, "bilinear", kWidth, kHeight), reference);
  const float trilinearError =
      rootMeanSquareDifference(recedingFloor(directory_, "trilinear", kWidth, kHeight), reference);
  EXPECT_LT(trilinearError, 0.75f * bilinearError)
      << "bilinear " << bilinearError << ", trilinear " << trilinearError;
}

TEST_F(TextureSceneFile, DressesAnUntexturedMd2ModelInItsSkin) {
  const std::filesystem::path path = directory_ / "md2.yaml";
  std::ofstream(path) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 40}\n"
                         "materials:\n"
                         "  skin: {color: [1, 1, 1]}\n"
                         "  painted: {texture: {image: textures/red.png}}\n"
                         "objects:\n"
                         "  - mesh: {file: "
                      << (kSydney / "sydney.md2").string()
                      << ", material: skin}\n"
                         "  - mesh: {file: "
                      << (kSydney / "sydney.md2").string()
                      << ", material: skin}\n"
                         "  - mesh: {file: "
                      << (kSydney / "sydney.md2").string() << ", material: painted}\n";
  const Scene scene = loadSceneFile(path);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[2].name, "skin with sydney.pcx");
  ASSERT_TRUE(scene.materials[2].texture);
  EXPECT_EQ(scene.shapes[0]->material(), 2);
  EXPECT_EQ(scene.shapes[1]->material(), 2);
  EXPECT_EQ(scene.shapes[2]->material(), 1);
  // The skin's texel at the middle of its first row, where v = 1.
  const Image skin = readImage(kSydney / "sydney.pcx");
  SurfacePoint top(Vec3(0.0f), Vec3(0, 1, 0), Vec2((154.0f + 0.5f) / 308.0f, 1.0f - 0.5f / 193.0f));
  expectColor(surfaceColors(scene.materials[2], top).color, skin.at(154, 0));
}

TEST_F(TextureSceneFile, WearsASkinWithoutItsPaletteMarkerAndWarns) {
  // Sydney's skin with the 0x0C byte before its palette taken out, as some
  // Quake II skins were written.
  std::ifstream original(kSydney / "sydney.pcx", std::ios::binary);
  std::string skin{std::istreambuf_iterator<char>(original), {}};
  skin.erase(skin.size() - 769, 1);
  std::ofstream(directory_ / "sydney.pcx", std::ios::binary) << skin;
  std::filesystem::copy_file(kSydney / "sydney.md2", directory_ / "sydney.md2");
  const std::filesystem::path path = directory_ / "scene.yaml";
  std::ofstream(path) << "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                         "materials: {skin: {}}\n"
                         "objects:\n"
                         "  - mesh: {file: sydney.md2, material: skin}\n";
  const Scene scene = loadSceneFile(path);
  EXPECT_EQ(scene.warnings,
            std::vector<std::string>{
                path.string() + ":4:18: warning: " + (directory_ / "sydney.pcx").string() +
                ": the 8-bit PCX image's palette lacks its 0x0C marker byte; read the last 768 "
                "bytes as the palette"});
  const Image worn = readImage(directory_ / "sydney.pcx");
  const Image intact = readImage(kSydney / "sydney.pcx");
  EXPECT_EQ(worn.pixels(), intact.pixels());
}

}  // namespace
}  // namespace rise
