// Carpenter's A-buffer as the z-buffer's transparency: stacks of coloured
// transparent squares over an opaque one, submitted in random orders, give
// at every pixel away from an edge the colour a formula in the test computes
// from the squares the pixel's ray passes through, and the image of the
// z-buffer that sorts its transparent polygons; transparent squares that
// pierce each other, which no order of whole polygons draws right, the
// formula's colour on both sides of the crossing; the classic scene's glass
// sphere the sorted z-buffer's picture; and the counters say what the lists
// held.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "support/raster_testing.hpp"
#include "support/transparency_testing.hpp"

namespace rise {
namespace {

using raster_testing::render;
using namespace transparency_testing;

RenderResult renderWith(Transparency transparency, const Scene& scene, RenderSettings settings) {
  settings.transparency = transparency;
  return render("z-buffer", scene, settings);
}

// A square of the stack: where it is and what it is made of.
struct Square {
  Vec2 centre;
  float z;
  int material;
};

// What the ray through a pixel's centre meets, nearest first, as far as the
// first opaque square: the squares the formula blends. `nearEdge` is set
// when the ray passes within `margin` of a square's edge, where the pixel's
// coverage is a matter of rounding.
struct RayThroughStack {
  std::vector<Square> met;
  bool nearEdge = false;
};

RayThroughStack throughStack(const Scene& scene, const Ray& ray, std::vector<Square> squares,
                             float margin) {
  std::sort(squares.begin(), squares.end(),
            [](const Square& a, const Square& b) { return a.z < b.z; });
  RayThroughStack through;
  for (const Square& square : squares) {
    const Vec3 at = ray.origin + ray.direction * ((square.z - ray.origin.z) / ray.direction.z);
    const float inside =
        1.0f - std::max(std::abs(at.x - square.centre.x), std::abs(at.y - square.centre.y));
    if (std::abs(inside) < margin) through.nearEdge = true;
    if (inside <= 0.0f) continue;
    through.met.push_back(square);
    if (!scene.materials[static_cast<std::size_t>(square.material)].isTransparent()) break;
  }
  return through;
}

// The colour the formula gives: the opaque square's own light or the
// background, then each transparent square over it, farthest first.
Color formulaColour(const Scene& scene, const std::vector<Square>& met) {
  Color colour = scene.image.background;
  for (auto square = met.rbegin(); square != met.rend(); ++square) {
    const Material& material = scene.materials[static_cast<std::size_t>(square->material)];
    colour = material.isTransparent() ? over(material, ownLight(scene, material), colour)
                                      : ownLight(scene, material);
  }
  return colour;
}

// Five transparent squares of five colours and an opaque one (material 0),
// added to the scene in the order given.
Scene stackScene(const std::vector<Square>& squares) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0, 0, -9), 160, 110);
  scene.ambient = Color(0.9f);
  const Color colours[] = {{0.9f, 0.3f, 0.2f},
                           {0.2f, 0.5f, 0.9f},
                           {0.3f, 0.9f, 0.3f},
                           {0.9f, 0.9f, 0.2f},
                           {0.7f, 0.2f, 0.9f}};
  for (int i = 0; i < 5; ++i)
    scene.materials.push_back(transparent(colours[i], 0.5f + 0.1f * static_cast<float>(i)));
  for (const Square& square : squares)
    addSquare(scene, square.centre.x, square.centre.y, square.z, square.material);
  return scene;
}

// The six squares (material 0, the opaque grey, among them) at random
// places, each at a depth of its own, 0.6 apart, drawn at random.
std::vector<Square> randomStack(std::mt19937& random) {
  std::uniform_real_distribution<float> place(-0.9f, 0.9f);
  std::vector<float> depths;
  for (int i = 0; i < 6; ++i) depths.push_back(0.6f * static_cast<float>(i) - 1.5f);
  std::shuffle(depths.begin(), depths.end(), random);
  std::vector<Square> squares;
  for (int material = 0; material < 6; ++material)
    squares.push_back({{place(random), place(random)}, depths[material], material});
  return squares;
}

TEST(ABuffer, StacksInAnyOrderBlendAsTheFormulaAndTheSortedZBuffer) {
  std::mt19937 random(19);
  for (int stack = 0; stack < 4; ++stack) {
    const std::vector<Square> squares = randomStack(random);
    const Scene scene = stackScene(squares);
    const RenderSettings settings = settingsFor(scene);
    const ViewFrame view(scene.camera, settings.width, settings.height);
    const RenderResult sorted = renderWith(Transparency::Sorted, scene, settings);
    std::vector<Square> order = squares;
    for (int shuffle = 0; shuffle < 3; ++shuffle) {
      std::shuffle(order.begin(), order.end(), random);
      const RenderResult fragments = renderWith(Transparency::ABuffer, stackScene(order), settings);
      std::size_t mostMet = 0;
      int compared = 0;
      for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
          const Color seen = fragments.image.at(x, y);
          EXPECT_LE(glm::length(seen - sorted.image.at(x, y)), 1e-5f)
              << "stack " << stack << " order " << shuffle << " pixel " << x << ", " << y;
          const RayThroughStack through = throughStack(
              scene, view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f),
              order, 0.02f);
          if (through.nearEdge) continue;
          const bool endsOpaque =
              !through.met.empty() &&
              !scene.materials[static_cast<std::size_t>(through.met.back().material)]
                   .isTransparent();
          mostMet = std::max(mostMet, through.met.size() - (endsOpaque ? 1 : 0));
          ++compared;
          if (glm::length(seen - formulaColour(scene, through.met)) > 1e-5f)
            ADD_FAILURE() << "stack " << stack << " pixel " << x << ", " << y;
        }
      EXPECT_GT(compared, settings.width * settings.height / 2);
      // The deepest stack away from the edges is in the lists, and no deeper.
      EXPECT_GE(fragments.stats.value("a_buffer_most_fragments"), static_cast<double>(mostMet));
      EXPECT_LE(fragments.stats.value("a_buffer_most_fragments"), 5.0);
      EXPECT_EQ(fragments.stats.value("transparent_blends"),
                sorted.stats.value("transparent_blends"));
    }
  }
}

// Two transparent squares that pierce each other along x = 0, one tilted:
// on each side of the crossing another is in front. The sorted z-buffer
// blends whole polygons in one order, right on one side only; the A-buffer
// orders each pixel's fragments.
TEST(ABuffer, SquaresThatPierceEachOtherBlendByDepthAtEachPixel) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0, 0, -8), 140, 100);
  scene.ambient = Color(0.8f);
  scene.materials.push_back(transparent(Color(0.9f, 0.3f, 0.2f), 0.6f));  // 1: red, upright
  scene.materials.push_back(transparent(Color(0.2f, 0.5f, 0.9f), 0.7f));  // 2: blue, tilted
  addSquare(scene, 0.0f, 0.0f, 0.0f, 1);
  scene.shapes.push_back(std::make_unique<ConvexPolygon>(
      std::vector<Vec3>{{-1.2f, -1, 0.6f}, {1.2f, -1, -0.6f}, {1.2f, 1, -0.6f}, {-1.2f, 1, 0.6f}},
      2));
  const Material& red = scene.materials[1];
  const Material& blue = scene.materials[2];
  const Color background = scene.image.background;
  const Color redLight = ownLight(scene, red), blueLight = ownLight(scene, blue);
  const RenderSettings settings = settingsFor(scene);
  const RenderResult fragments = renderWith(Transparency::ABuffer, scene, settings);
  const RenderResult sorted = renderWith(Transparency::Sorted, scene, settings);
  // Left, blue is behind red; right, in front.
  const Color left = over(red, redLight, over(blue, blueLight, background));
  const Color right = over(blue, blueLight, over(red, redLight, background));
  const Vec2 onLeft = pixelSeeing(scene, settings, Vec3(-0.5f, 0.0f, 0.0f));
  const Vec2 onRight = pixelSeeing(scene, settings, Vec3(0.5f, 0.0f, 0.0f));
  const auto at = [](const RenderResult& result, const Vec2& pixel) {
    return result.image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y));
  };
  expectNear(at(fragments, onLeft), left, "a-buffer, left");
  expectNear(at(fragments, onRight), right, "a-buffer, right");
  EXPECT_GT(
      std::max(glm::length(at(sorted, onLeft) - left), glm::length(at(sorted, onRight) - right)),
      0.01f)
      << "the sorted z-buffer should be wrong on one side";
}

// The classic scene's glass sphere, at sizes and shapes other than the
// example's: the same picture both ways, within the examples' tolerance.
TEST(ABuffer, TheClassicSceneLooksAsTheSortedZBufferDrawsIt) {
  const Scene scene = classicScene();
  for (const auto& [width, height] : {std::pair{170, 77}, std::pair{61, 95}}) {
    const RenderSettings settings = settingsAtSize(scene, width, height);
    const RenderResult fragments = renderWith(Transparency::ABuffer, scene, settings);
    const RenderResult sorted = renderWith(Transparency::Sorted, scene, settings);
    EXPECT_GT(fragments.stats.value("a_buffer_fragments"), 0.0);
    EXPECT_GT(fragments.stats.value("a_buffer_bytes"), 0.0);
    EXPECT_EQ(sorted.stats.value("a_buffer_fragments"), 0.0);
    EXPECT_LE(raster_testing::pixelsDiffering(fragments.image, sorted.image), width * height / 100)
        << width << " x " << height;
  }
}

}  // namespace
}  // namespace rise
