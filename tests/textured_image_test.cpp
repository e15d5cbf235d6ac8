// Textures in rendered images, by the ray tracer and the visible-surface
// algorithms alike: checker corners where the mapping puts them, straight
// lines on a receding floor, and bumps that change shading but not outlines
// or shadows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_file.hpp"
#include "scene/scene.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/textures/bump_map.hpp"
#include "scene/textures/perlin_noise.hpp"
#include "support/raster_testing.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

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
  RenderSettings settings = settingsFor(scene);
  expectCornerAtTheCentre(raster_testing::render("ray-tracing", scene, settings).image, kEven);
  expectCornerAtTheCentre(raster_testing::render("z-buffer", scene, settings).image, kEven);
}

TEST(TexturedImage, PutsThePlanesCheckerCornerWhereTheMappingSays) {
  // The plane's u = x and v = -z; the camera on -z sees +x to its left and
  // +z up: at top left 0 <= u < 1 and -1 <= v < 0, the odd square (0, -1).
  const Scene scene =
      checkerScene("{position: [0, 3, -4], look_at: [0, 0, 0], fov: 40}", "1",
                   "plane: {point: [0, 0, 0], normal: [0, 1, 0], material: checker}");
  RenderSettings settings = settingsFor(scene);
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
  RenderSettings settings = settingsFor(scene);
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
  const RenderSettings settings = settingsFor(smooth);
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
