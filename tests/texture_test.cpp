// Textures: the natural texture coordinates of every primitive, in the ray
// tracer and in the tessellations that the visible-surface algorithms draw;
// image textures and their filters; the PCX skins of MD2 models; Perlin's
// noise; and the `texture` key of the scene file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "core/image_io.hpp"
#include "core/pcx_file.hpp"
#include "raster/raster_testing.hpp"
#include "scene/bump_map.hpp"
#include "scene/image_texture.hpp"
#include "scene/mesh_file.hpp"
#include "scene/noise_texture.hpp"
#include "scene/normal_map.hpp"
#include "scene/perlin_noise.hpp"
#include "scene/scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_file.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/shape_testing.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/transformed_texture.hpp"

namespace rise {
namespace {

using shape_testing::expectUv;
using shape_testing::intersect;
using shape_testing::uvSeenAlong;

constexpr float kTolerance = 1e-4f;

// The distance between two u coordinates on a surface that wraps at u = 1.
float wrappedDistance(float a, float b) {
  const float d = std::abs(a - b);
  return std::min(d, 1.0f - d);
}

TEST(NaturalUv, SphereIsLongitudeAndLatitude) {
  const Sphere sphere(Vec3(0.0f), 2.0f, 0);
  // Seen from -z the facing point is at u = 1/4; u grows towards -x, to the
  // viewer's right; v is 0 at the south pole and 1 at the north.
  expectUv(uvSeenAlong(sphere, Vec3(0, 0, -5), Vec3(0, 0, 1)), {0.25f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(5, 0, 0), Vec3(-1, 0, 0)), {0.0f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(0, 0, 5), Vec3(0, 0, -1)), {0.75f, 0.5f});
  expectUv(uvSeenAlong(sphere, Vec3(-5, 0, 0), Vec3(1, 0, 0)), {0.5f, 0.5f});
  EXPECT_NEAR(uvSeenAlong(sphere, Vec3(0, 5, 0), Vec3(0, -1, 0)).y, 1.0f, kTolerance);
  EXPECT_NEAR(uvSeenAlong(sphere, Vec3(0, -5, 0), Vec3(0, 1, 0)).y, 0.0f, kTolerance);
  // 45 degrees north of the point facing -z: v = 3/4.
  const Vec3 north45 = Vec3(0.0f, std::sqrt(2.0f), -std::sqrt(2.0f));
  expectUv(uvSeenAlong(sphere, 3.0f * north45, -north45), {0.25f, 0.75f});
}

TEST(NaturalUv, BoxMapsEachFaceOntoTheUnitSquareSeenFromOutside) {
  const Box box(Vec3(0.0f), Vec3(2.0f, 1.0f, 4.0f), 0);
  // The -z face, seen from -z: u grows to the right (-x), v up.
  expectUv(uvSeenAlong(box, Vec3(0.5f, 0.75f, -5), Vec3(0, 0, 1)), {0.75f, 0.75f});
  // The +z face, seen from +z: right is +x.
  expectUv(uvSeenAlong(box, Vec3(0.5f, 0.75f, 9), Vec3(0, 0, -1)), {0.25f, 0.75f});
  // The +x face, seen from +x: right is -z.
  expectUv(uvSeenAlong(box, Vec3(7, 0.25f, 1), Vec3(-1, 0, 0)), {0.75f, 0.25f});
  // The top: u along x, v along -z.
  expectUv(uvSeenAlong(box, Vec3(1.5f, 3, 1), Vec3(0, -1, 0)), {0.75f, 0.75f});
  // The bottom: u along x, v along +z.
  expectUv(uvSeenAlong(box, Vec3(1.5f, -3, 1), Vec3(0, 1, 0)), {0.75f, 0.25f});
}

TEST(NaturalUv, CylinderSideGoesAroundAndAlongTheAxisAndCapsArePlanar) {
  const Cylinder cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 4.0f, 0);
  expectUv(uvSeenAlong(cylinder, Vec3(0, 1, -5), Vec3(0, 0, 1)), {0.25f, 0.25f});
  expectUv(uvSeenAlong(cylinder, Vec3(-5, 3, 0), Vec3(1, 0, 0)), {0.5f, 0.75f});
  expectUv(uvSeenAlong(cylinder, Vec3(0, 9, 0), Vec3(0, -1, 0)), {0.5f, 0.5f});
  expectUv(uvSeenAlong(cylinder, Vec3(0, -9, 0), Vec3(0, 1, 0)), {0.5f, 0.5f});
  const Vec2 rim = uvSeenAlong(cylinder, Vec3(0.999f, 9, 0), Vec3(0, -1, 0));
  EXPECT_NEAR(glm::length(rim - Vec2(0.5f)), 0.4995f, kTolerance);
}

TEST(NaturalUv, ConeSideRunsFromBaseToApex) {
  const Cone cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0);
  // Halfway up, the side is 0.5 from the axis.
  expectUv(uvSeenAlong(cone, Vec3(0, 1, -5), Vec3(0, 0, 1)), {0.25f, 0.5f});
  expectUv(uvSeenAlong(cone, Vec3(0, -9, 0), Vec3(0, 1, 0)), {0.5f, 0.5f});
}

TEST(NaturalUv, TriangleIsBarycentric) {
  const Triangle triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 0)}, 0);
  expectUv(uvSeenAlong(triangle, Vec3(1, 0.5f, -3), Vec3(0, 0, 1)), {0.25f, 0.25f});
}

TEST(NaturalUv, PolygonMapsItsBoundingRectangleOntoTheUnitSquare) {
  const ConvexPolygon quad({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0);
  expectUv(uvSeenAlong(quad, Vec3(1, 1.5f, -3), Vec3(0, 0, 1)), {0.25f, 0.75f});
}

Tessellation tessellationOf(const Shape& shape, int level = 4) {
  Tessellation out;
  TessellationSettings settings;
  settings.level = level;
  shape.tessellate(settings, out);
  return out;
}

// Each vertex of the tessellation has the coordinates the ray tracer finds
// there (up to the seam, where 0 and 1 meet), and no triangle's u spans
// more than a few segments: a triangle across the seam would smear the whole
// texture backwards over it.
void expectTessellationAgreesWithRayTracing(const Shape& shape, float largestUSpan,
                                            bool uSingularAtVEnds = false) {
  const Tessellation tessellation = tessellationOf(shape);
  std::size_t checked = 0;
  for (const SurfaceVertex& vertex : tessellation.vertices) {
    // Straight in towards the vertex, from outside, along its normal; a ray
    // that grazes an edge may miss, or find the face across the edge.
    const Vec3 origin = vertex.position + 0.5f * vertex.normal;
    const auto result = intersect(shape, Ray{origin, -vertex.normal});
    if (!result.found || glm::dot(result.surface.normal, vertex.normal) < 0.999f) continue;
    ++checked;
    // At the poles and the apex u is not defined.
    const bool atSingularEnd = uSingularAtVEnds && (vertex.uv.y > 0.9999f || vertex.uv.y < 1e-4f);
    if (!atSingularEnd) {
      EXPECT_LT(wrappedDistance(result.surface.uv.x, vertex.uv.x), 1e-3f);
    }
    EXPECT_NEAR(result.surface.uv.y, vertex.uv.y, 1e-3f);
  }
  EXPECT_GT(checked, tessellation.vertices.size() / 4);
  for (const auto& triangle : tessellation.triangles) {
    float low = 1.0f, high = 0.0f;
    for (int corner : triangle) {
      low = std::min(low, tessellation.vertices[corner].uv.x);
      high = std::max(high, tessellation.vertices[corner].uv.x);
    }
    EXPECT_LE(high - low, largestUSpan);
  }
}

TEST(NaturalUv, SphereTessellationHasTheRayTracersCoordinatesAndNoSeamGap) {
  expectTessellationAgreesWithRayTracing(Sphere(Vec3(1, 2, 3), 2.0f, 0), 1.01f / 16.0f, true);
}

TEST(NaturalUv, CylinderTessellationHasTheRayTracersCoordinatesAndNoSeamGap) {
  expectTessellationAgreesWithRayTracing(Cylinder(Vec3(0.0f), Vec3(1, 1, 0), 1.0f, 2.0f, 0), 1.0f);
}

TEST(NaturalUv, ConeTessellationHasTheRayTracersCoordinates) {
  expectTessellationAgreesWithRayTracing(Cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0), 1.0f,
                                         true);
}

TEST(NaturalUv, FlatShapesTessellateWithTheRayTracersCoordinates) {
  expectTessellationAgreesWithRayTracing(Box(Vec3(-1.0f), Vec3(2.0f, 1.0f, 3.0f), 0), 1.0f);
  expectTessellationAgreesWithRayTracing(Triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 1)}, 0),
                                         1.0f);
  expectTessellationAgreesWithRayTracing(
      ConvexPolygon({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0), 1.0f);
}

TEST(NaturalUv, CurvedSideTrianglesSpanOneSegmentOfU) {
  // 16 segments around at level 4: every side triangle spans 1/16 of u.
  const Tessellation cylinder = tessellationOf(Cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 1.0f, 0));
  for (const auto& triangle : cylinder.triangles) {
    const SurfaceVertex& a = cylinder.vertices[triangle[0]];
    if (glm::dot(a.normal, Vec3(0, 1, 0)) != 0.0f) continue;  // a cap
    float low = 1.0f, high = 0.0f;
    for (int corner : triangle) {
      low = std::min(low, cylinder.vertices[corner].uv.x);
      high = std::max(high, cylinder.vertices[corner].uv.x);
    }
    EXPECT_NEAR(high - low, 1.0f / 16.0f, 1e-5f);
  }
}

// A 2 x 2 image: red, green on top; blue, white below.
std::shared_ptr<const Image> fourTexels() {
  auto image = std::make_shared<Image>(2, 2);
  image->at(0, 0) = Color(1, 0, 0);
  image->at(1, 0) = Color(0, 1, 0);
  image->at(0, 1) = Color(0, 0, 1);
  image->at(1, 1) = Color(1, 1, 1);
  return image;
}

void expectColor(const Color& actual, const Color& expected) {
  EXPECT_NEAR(actual.r, expected.r, kTolerance);
  EXPECT_NEAR(actual.g, expected.g, kTolerance);
  EXPECT_NEAR(actual.b, expected.b, kTolerance);
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
  ASSERT_EQ(texture.levels().size(), 3u);
  EXPECT_EQ(texture.levels()[1].width(), 2);
  EXPECT_EQ(texture.levels()[2].width(), 1);
  expectColor(texture.levels()[2].at(0, 0), Color(0.5f));
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
  const Image pcx = readTextureImage(kSydney / "sydney.pcx");
  const Image bmp = readTextureImage(kSydney / "sydney.bmp");
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

class TextureSceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        std::filesystem::temp_directory_path() /
        ("rise-texture-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(directory_ / "textures");
    writeImage(Image(4, 2, Color(1.0f, 0.0f, 0.0f)), directory_ / "textures/red.png");
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

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

  std::filesystem::path directory_;
};

TEST_F(TextureSceneFile, ReadsAnImageRelativeToTheSceneFile) {
  const Scene scene = load("{image: textures/red.png, filter: nearest, scale: 2, rotate: 30}");
  ASSERT_TRUE(scene.materials[0].texture);
  SurfacePoint point(Vec3(0.0f), Vec3(0, 0, -1), Vec2(0.3f, 0.6f));
  expectColor(scene.materials[0].colorAt(point), Color(1, 0, 0));
}

TEST_F(TextureSceneFile, ReadsTheProceduralTextures) {
  for (const std::string kind : {"perlin", "marble", "wood"}) {
    const Scene scene = load("{" + kind + ": {colors: [[0, 0, 0], [1, 1, 1]], scale: 2}}");
    EXPECT_TRUE(scene.materials[0].texture) << kind;
  }
  const Scene checker = load("{checker: {colors: [[0, 0, 0], [1, 1, 1]], size: 0.5}}");
  SurfacePoint point(Vec3(0.0f), Vec3(0, 0, -1), Vec2(0.75f, 0.25f));
  expectColor(checker.materials[0].colorAt(point), Color(1, 1, 1));
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
  EXPECT_TRUE(shape_testing::nearlyEqual(scene.materials[0].shadingNormalAt(surface),
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

TEST(Md2Skin, IsTheSkinNamedLikeTheModelOrTheFoldersOnlyPcx) {
  const std::filesystem::path models = std::filesystem::path(RISE_SOURCE_DIR) / "examples/models";
  EXPECT_EQ(findMd2Skin(models / "sydney/sydney.md2"), models / "sydney/sydney.pcx");
  EXPECT_EQ(findMd2Skin(models / "ratamahatta/tris.md2"), models / "ratamahatta/Ratamahatta.pcx");
  EXPECT_EQ(findMd2Skin(models / "spot/spot.md2"), std::nullopt);
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
  const Image skin = readTextureImage(kSydney / "sydney.pcx");
  SurfacePoint top(Vec3(0.0f), Vec3(0, 1, 0), Vec2((154.0f + 0.5f) / 308.0f, 1.0f - 0.5f / 193.0f));
  expectColor(scene.materials[2].colorAt(top), skin.at(154, 0));
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
  EXPECT_TRUE(shape_testing::nearlyEqual(bump.shadingNormalAt(surface),
                                         glm::normalize(Vec3(-0.5f, 1.0f, 0.0f))));
  // Texture coordinates stretched twice as far: half the slope in space.
  surface.dpdu = Vec3(2, 0, 0);
  EXPECT_TRUE(shape_testing::nearlyEqual(bump.shadingNormalAt(surface),
                                         glm::normalize(Vec3(-0.25f, 1.0f, 0.0f))));
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
    return NormalMap(std::make_shared<Uniform>(color)).shadingNormalAt(surface);
  };
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(0.5f, 0.5f, 1.0f)), Vec3(0, 1, 0)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(1.0f, 0.5f, 0.5f)), Vec3(1, 0, 0)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(0.5f, 1.0f, 0.5f)), Vec3(0, 0, -1)));
  EXPECT_TRUE(shape_testing::nearlyEqual(normalFor(Color(1.0f, 0.5f, 1.0f)),
                                         glm::normalize(Vec3(1, 1, 0))));
}

// dP/du and dP/dv are the rates of change of the position with the texture
// coordinates: a step along dP/du (back onto the surface) moves u alone.
void expectTangentsMatchTheMapping(const Shape& shape, const Vec3& origin, const Vec3& direction) {
  const auto at = intersect(shape, Ray{origin, direction});
  ASSERT_TRUE(at.found);
  const float step = 1e-3f;
  for (int axis = 0; axis < 2; ++axis) {
    const Vec3 tangent = axis == 0 ? at.surface.dpdu : at.surface.dpdv;
    const Vec3 moved = at.surface.position + step * tangent;
    const auto there = intersect(shape, Ray{moved + 0.1f * at.surface.normal, -at.surface.normal});
    ASSERT_TRUE(there.found);
    const Vec2 change = (there.surface.uv - at.surface.uv) / step;
    EXPECT_NEAR(change[axis], 1.0f, 2e-2f) << "axis " << axis;
    EXPECT_NEAR(change[1 - axis], 0.0f, 2e-2f) << "axis " << axis;
  }
}

TEST(NaturalUv, TangentsAreTheDerivativesOfTheMapping) {
  expectTangentsMatchTheMapping(Sphere(Vec3(0.0f), 2.0f, 0), Vec3(1, 0.5f, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Box(Vec3(0.0f), Vec3(2, 1, 4), 0), Vec3(0.5f, 0.6f, -5),
                                Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Box(Vec3(0.0f), Vec3(2, 1, 4), 0), Vec3(1.5f, 3, 1),
                                Vec3(0, -1, 0));
  const Cylinder cylinder(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 4.0f, 0);
  expectTangentsMatchTheMapping(cylinder, Vec3(0.3f, 1, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(cylinder, Vec3(0.3f, 9, 0.2f), Vec3(0, -1, 0));
  expectTangentsMatchTheMapping(Cone(Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0),
                                Vec3(0.2f, 0.7f, -5), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(Triangle({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 1)}, 0),
                                Vec3(1, 0.5f, -3), Vec3(0, 0, 1));
  expectTangentsMatchTheMapping(
      ConvexPolygon({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0)}, 0),
      Vec3(1, 0.5f, -3), Vec3(0, 0, 1));
}

const Color kEven(1.0f, 1.0f, 1.0f);
const Color kOdd(0.0f, 0.0f, 1.0f);

// A scene of one shape with a checker of white (even) and blue (odd)
// squares, lit by ambient light alone so that the image is the texture.
Scene checkerScene(const std::string& camera, const std::string& checkerSize,
                   const std::string& object) {
  return loadScene("image: {width: 64, height: 48}\ncamera: " + camera +
                       "\nambient: [1, 1, 1]\n"
                       "materials:\n  checker: {ka: 1, kd: 0, texture: {checker: {colors: "
                       "[[1, 1, 1], [0, 0, 1]], size: " +
                       checkerSize + "}}}\nobjects:\n  - " + object + "\n",
                   "checker.yaml");
}

// The four pixels around the image's centre, which the camera aims at a
// corner of four squares: `topLeft` there and at bottom right, the other
// colour at top right and bottom left.
void expectCornerAtTheCentre(const Image& image, const Color& topLeft) {
  const Color& other = topLeft == kEven ? kOdd : kEven;
  const int x = image.width() / 2, y = image.height() / 2;
  const auto expectNear = [](const Color& actual, const Color& expected) {
    EXPECT_LT(glm::length(actual - expected), 1e-3f)
        << actual.r << " " << actual.g << " " << actual.b;
  };
  expectNear(image.at(x - 1, y - 1), topLeft);
  expectNear(image.at(x, y - 1), other);
  expectNear(image.at(x - 1, y), other);
  expectNear(image.at(x, y), topLeft);
}

TEST(TexturedImage, PutsTheSpheresCheckerCornerWhereTheMappingSays) {
  // Seen from -z, the sphere's point at u = 1/4, v = 1/2 faces the camera:
  // to its top left u < 1/4 and v > 1/2, the even square (0, 2).
  const Scene scene = checkerScene("{position: [0, 0, -5], look_at: [0, 0, 0], fov: 30}", "0.25",
                                   "sphere: {center: [0, 0, 0], radius: 1, material: checker}");
  RenderSettings settings = raster_testing::settingsFor(scene);
  expectCornerAtTheCentre(raster_testing::render("ray-tracing", scene, settings).image, kEven);
  expectCornerAtTheCentre(raster_testing::render("z-buffer", scene, settings).image, kEven);
}

TEST(TexturedImage, PutsThePlanesCheckerCornerWhereTheMappingSays) {
  // The plane's u = x and v = -z; the camera on -z sees +x to its left and
  // +z up: at top left 0 <= u < 1 and -1 <= v < 0, the odd square (0, -1).
  const Scene scene =
      checkerScene("{position: [0, 3, -4], look_at: [0, 0, 0], fov: 40}", "1",
                   "plane: {point: [0, 0, 0], normal: [0, 1, 0], material: checker}");
  RenderSettings settings = raster_testing::settingsFor(scene);
  expectCornerAtTheCentre(raster_testing::render("ray-tracing", scene, settings).image, kOdd);
  expectCornerAtTheCentre(raster_testing::render("z-buffer", scene, settings).image, kOdd);
}

// A floor of two large triangles, seen at a grazing angle: interpolating the
// texture coordinates linearly in the image would bend the checker's lines
// across each triangle; perspective-correct interpolation draws them as the
// ray tracer sees them, straight.
TEST(TexturedImage, KeepsAFloorsCheckerLinesStraightInEveryAlgorithm) {
  const Scene scene = checkerScene(
      "{position: [0, 1, -6], look_at: [0, 0, 4], fov: 50}", "0.125",
      "polygon: {vertices: [[-4, 0, -4], [4, 0, -4], [4, 0, 12], [-4, 0, 12]], material: checker}");
  RenderSettings settings = raster_testing::settingsFor(scene);
  const Image rays = raster_testing::render("ray-tracing", scene, settings).image;
  for (std::string_view algorithm : raster_testing::kAlgorithms) {
    const Image drawn = raster_testing::render(algorithm, scene, settings).image;
    int differing = 0;
    for (int y = 0; y < rays.height(); ++y)
      for (int x = 0; x < rays.width(); ++x)
        differing += glm::length(rays.at(x, y) - drawn.at(x, y)) > 0.5f ? 1 : 0;
    // Pixel centres on a line may fall to either side by rounding.
    EXPECT_LE(differing, rays.width() * rays.height() / 100) << algorithm;
  }
}

// A bumped sphere on a plain floor, lit from above.
Scene bumpScene(bool bumped) {
  const std::string bump =
      bumped ? ", bump: {map: {perlin: {colors: [[0, 0, 0], [1, 1, 1]], scale: 6}}, strength: 0.3}"
             : "";
  return loadScene(
      "image: {width: 64, height: 48}\n"
      "camera: {position: [0, 2, -5], look_at: [0, 0.8, 0], fov: 40}\n"
      "lights:\n  - point: {position: [2, 6, -3], color: [1, 1, 1]}\n"
      "materials:\n  floor: {color: [0.8, 0.8, 0.8]}\n  ball: {color: [0.9, 0.3, 0.2], ks: 0.5, "
      "n: 30" +
          bump +
          "}\n"
          "objects:\n  - plane: {point: [0, 0, 0], normal: [0, 1, 0], material: floor}\n"
          "  - sphere: {center: [0, 1, 0], radius: 1, material: ball}\n",
      "bump.yaml");
}

TEST(TexturedImage, ABumpMapChangesShadingButNotSilhouettesOrShadows) {
  const Scene smooth = bumpScene(false), bumped = bumpScene(true);
  const RenderSettings settings = raster_testing::settingsFor(smooth);
  for (std::string_view algorithm : {"ray-tracing", "z-buffer"}) {
    const RenderResult plain = raster_testing::render(algorithm, smooth, settings);
    const RenderResult tilted = raster_testing::render(algorithm, bumped, settings);
    const Image& plainDepth = plain.buffers.at("depth");
    const Image& tiltedDepth = tilted.buffers.at("depth");
    int changedOnTheBall = 0, changedOnTheFloor = 0, ballPixels = 0;
    for (int y = 0; y < plainDepth.height(); ++y) {
      for (int x = 0; x < plainDepth.width(); ++x) {
        ASSERT_EQ(plainDepth.at(x, y), tiltedDepth.at(x, y)) << algorithm << " " << x << " " << y;
        const bool onTheBall =
            std::isfinite(plainDepth.at(x, y).x) && plain.buffers.at("normal").at(x, y).y < 0.999f;
        const bool changed = glm::length(plain.image.at(x, y) - tilted.image.at(x, y)) > 1e-3f;
        ballPixels += onTheBall ? 1 : 0;
        (onTheBall ? changedOnTheBall : changedOnTheFloor) += changed ? 1 : 0;
      }
    }
    // The floor, its shadow of the ball included, is untouched.
    EXPECT_EQ(changedOnTheFloor, 0) << algorithm;
    EXPECT_GT(changedOnTheBall, ballPixels / 2) << algorithm;
  }
}

}  // namespace
}  // namespace rise
