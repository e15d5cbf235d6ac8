// Projected mappings drawn: a texel at a known place of a textured object
// lands at the same pixel in the ray tracer's image and the visible-surface
// algorithms', as the object moves and when a mesh takes the mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "io/image_io.hpp"
#include "io/scene_error.hpp"
#include "io/scene_file.hpp"
#include "scene/scene.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/mesh_mapping.hpp"
#include "scene/textures/surface_mapping.hpp"
#include "support/raster_testing.hpp"
#include "support/shape_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

using shape_testing::expectUv;
using shape_testing::uSpan;
using shape_testing::uvSeenAlong;

// A scene of one object, lit by ambient light alone so that the image is the
// texture: an image of 8 x 4 texels, each its own colour, read nearest.
class MappedScene : public TemporaryFolderTest {
 protected:
  void SetUp() override {
    TemporaryFolderTest::SetUp();
    Image texels(8, 4);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 8; ++x)
        texels.at(x, y) = Color(static_cast<float>(x) / 7.0f, static_cast<float>(y) / 3.0f,
                                static_cast<float>((x + y) % 2));
    writeImage(texels, directory_ / "texels.png");
    texels_ = readImage(directory_ / "texels.png");
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  // The object seen from `eye`, looking at `target`, in an odd-sized image
  // whose middle pixel looks straight at the target.
  Scene load(const std::string& object, const Vec3& eye, const Vec3& target) {
    const std::filesystem::path path = directory_ / "scene.yaml";
    std::ofstream(path) << "image: {width: 65, height: 49}\ncamera: {position: [" << eye.x << ", "
                        << eye.y << ", " << eye.z << "], look_at: [" << target.x << ", " << target.y
                        << ", " << target.z
                        << "], fov: 40}\nambient: [1, 1, 1]\n"
                           "materials:\n  texels: {ka: 1, kd: 0, texture: {image: texels.png, "
                           "filter: nearest}}\nobjects:\n  - "
                        << object << "\n";
    return loadSceneFile(path);
  }

  // The texel whose centre is at `uv`, which each algorithm should see at
  // the middle pixel, and the pixels where the visible-surface algorithms see
  // another colour than the ray tracer.
  void expectTexelInTheMiddle(const Scene& scene, const Vec2& uv) {
    const int column = static_cast<int>(std::floor(uv.x * 8.0f));
    const int row = static_cast<int>(std::floor((1.0f - uv.y) * 4.0f));
    ASSERT_NEAR(uv.x * 8.0f, static_cast<float>(column) + 0.5f, 1e-3f) << "not a texel's centre";
    ASSERT_NEAR((1.0f - uv.y) * 4.0f, static_cast<float>(row) + 0.5f, 1e-3f);
    const Color expected = texels_.at(column, row);
    const RenderSettings settings = settingsFor(scene);
    const Image rays = raster_testing::render("ray-tracing", scene, settings).image;
    const int x = settings.width / 2, y = settings.height / 2;
    EXPECT_LT(glm::length(rays.at(x, y) - expected), 1e-3f) << "ray-tracing";
    for (std::string_view algorithm : raster_testing::kAlgorithms) {
      const Image drawn = raster_testing::render(algorithm, scene, settings).image;
      EXPECT_LT(glm::length(drawn.at(x, y) - expected), 1e-3f) << algorithm;
      int differing = 0;
      for (int py = 0; py < rays.height(); ++py)
        for (int px = 0; px < rays.width(); ++px)
          differing += glm::length(rays.at(px, py) - drawn.at(px, py)) > 1e-3f ? 1 : 0;
      // Pixel centres near a texel's edge may fall to either side, and a
      // box mapping's faces meet along the triangles' edges.
      EXPECT_LE(differing, rays.width() * rays.height() / 100) << algorithm;
    }
  }

  Image texels_;
};

// The direction from a turning mapping's centre at which u and v are those
// given, for y up.
Vec3 directionAt(const Vec2& uv, bool cylindrical) {
  const float turn = 2.0f * kPi * uv.x;
  const float up = cylindrical ? 0.0f : (uv.y - 0.5f) * kPi;
  return {std::cos(up) * std::cos(turn), std::sin(up), -std::cos(up) * std::sin(turn)};
}

TEST_F(MappedScene, SphericalPutsTheTexelAtItsLongitudeAndLatitude) {
  // Column 2, row 1: u = 2.5 / 8, v = 1 - 1.5 / 4.
  const Vec2 uv(2.5f / 8.0f, 0.625f);
  const Vec3 centre(0, 1, 0);
  expectTexelInTheMiddle(
      load("box: {min: [-1, 0, -1], max: [1, 2, 1], material: texels, mapping: spherical}",
           centre + 6.0f * directionAt(uv, false), centre),
      uv);
}

TEST_F(MappedScene, SphericalMovesWithTheObject) {
  // Turned a quarter about y and moved: the object's +x side, where u = 0,
  // faces -z, and the texel at u = 0.5 / 8 lies a little to its right.
  const Vec2 uv(0.5f / 8.0f, 0.625f);
  const Vec3 local = directionAt(uv, false);
  const Vec3 world(local.z, local.y, -local.x);  // turned a quarter about y
  const Vec3 centre(3, 1, 2);
  expectTexelInTheMiddle(
      load("box: {min: [-1, -1, -1], max: [1, 1, 1], material: texels, mapping: spherical, "
           "transform: {rotate: [0, 90, 0], translate: [3, 1, 2]}}",
           centre + 6.0f * world, centre),
      uv);
}

TEST_F(MappedScene, CylindricalPutsTheTexelAtItsTurnAndHeight) {
  // Column 5, row 2: u = 5.5 / 8, v = 1 - 2.5 / 4, a quarter of the way up.
  const Vec2 uv(5.5f / 8.0f, 0.375f);
  expectTexelInTheMiddle(
      load("cylinder: {base: [0, 0, 0], axis: [0, 1, 0], radius: 1, height: 4, material: "
           "texels, mapping: cylindrical}",
           Vec3(0, 1.5f, 0) + 6.0f * directionAt(uv, true),
           Vec3(0, 1.5f, 0) + directionAt(uv, true)),
      uv);
}

TEST_F(MappedScene, PlanarPutsTheTexelOnTheFront) {
  // Column 6, row 3: u = 6.5 / 8 to the right seen from -z, v = 0.5 / 4.
  const Vec2 uv(6.5f / 8.0f, 0.125f);
  const Vec3 onTheBox(1.0f - 2.0f * uv.x, -1.0f + 2.0f * uv.y, -0.5f);
  expectTexelInTheMiddle(
      load("sphere: {center: [0, 0, 0], radius: 1, material: texels, mapping: planar}",
           onTheBox + Vec3(0, 0, -6), onTheBox),
      uv);
}

TEST_F(MappedScene, BoxPutsTheTexelOnTheFaceTheSurfaceFaces) {
  // Near the top, facing +y: u along x, v along -z; column 3, row 1.
  const Vec2 uv(3.5f / 8.0f, 0.625f);
  const Vec3 onTheTop(-1.0f + 2.0f * uv.x, 1.0f, 1.0f - 2.0f * uv.y);
  expectTexelInTheMiddle(
      load("sphere: {center: [0, 0, 0], radius: 1, material: texels, mapping: box}",
           onTheTop + Vec3(0.5f, 6, -1), onTheTop),
      uv);
}

TEST_F(MappedScene, AMeshTakesTheMappingAsItLoadsWithoutASmearAtTheSeam) {
  // A cube of eight shared corners, in the spherical mapping: the seam runs
  // down the middle of its +x face.
  const Vec2 uv(7.5f / 8.0f, 0.625f);
  const Vec3 centre(0.0f);
  const Scene scene = load(
      "mesh: {vertices: [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], "
      "[1, -1, 1], [1, 1, 1], [-1, 1, 1]], faces: [[0, 3, 2, 1], [4, 5, 6, 7], [0, 4, 7, "
      "3], [1, 2, 6, 5], [3, 7, 6, 2], [0, 1, 5, 4]], material: texels, mapping: spherical}",
      centre + 6.0f * directionAt(uv, false), centre);
  Tessellation tessellation;
  scene.shapes[0]->tessellate(TessellationSettings{}, tessellation);
  // Each side spans a quarter turn; the top and bottom, around the poles,
  // turn all the way.
  for (const auto& triangle : tessellation.triangles) {
    const Vec3 normal = tessellation.vertices[triangle[0]].normal;
    if (normal.y == 0.0f) {
      EXPECT_LE(uSpan(tessellation, triangle), 0.25f + 1e-5f);
    }
  }
  // On the seam, u is 1 (or 0) and v a half.
  expectUv(uvSeenAlong(*scene.shapes[0], Vec3(5, 0, 0), Vec3(-1, 0, 0)), {1.0f, 0.5f});
  expectTexelInTheMiddle(scene, uv);
}

}  // namespace
}  // namespace rise
