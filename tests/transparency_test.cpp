// Transparency in depth sort, the z-buffer and the scanline algorithm:
// coloured transparent squares stacked over a background and over an opaque
// square give the colour a formula in the test computes, each surface's own
// light plus what is behind it filtered by its transmission times its colour;
// with an index of refraction of 1, which bends no ray, the same image as
// Whitted's ray tracer, shadows through the squares included; and the glass
// sphere of the classic scene looks the same to the three.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_file.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using raster_testing::render;

constexpr std::string_view kBlendingAlgorithms[] = {"depth-sort", "z-buffer", "scanline"};

// A square of side 2 facing the camera (on -z) at depth z, centred at
// (x, y), of material `material`.
void addSquare(Scene& scene, float x, float y, float z, int material) {
  scene.shapes.push_back(std::make_unique<ConvexPolygon>(
      std::vector<Vec3>{{x - 1, y - 1, z}, {x + 1, y - 1, z}, {x + 1, y + 1, z}, {x - 1, y + 1, z}},
      material));
}

Material transparent(const Color& color, float transmission) {
  Material material;
  material.color = color;
  material.ka = 1.0f;
  material.kd = 0.0f;
  material.transmission = transmission;
  material.ior = 1.0f;
  return material;
}

// Ambient light alone: each surface's own light is Ia ka C (1 - t).
Color ownLight(const Scene& scene, const Material& material) {
  return scene.ambient * material.ka * (1.0f - material.transmission) * material.color;
}

Color over(const Material& material, const Color& own, const Color& behind) {
  return own + material.transmission * material.color * behind;
}

void expectNear(const Color& seen, const Color& expected, std::string_view algorithm) {
  for (int channel = 0; channel < 3; ++channel)
    EXPECT_NEAR(seen[channel], expected[channel], 1e-5f) << algorithm << " channel " << channel;
}

// The pixel whose centre sees the point `at` of a plane facing the camera
// (z constant), or the nearest to it.
Vec2 pixelSeeing(const Scene& scene, const RenderSettings& settings, const Vec3& at) {
  const ViewFrame view(scene.camera, settings.width, settings.height);
  const Vec3 eye = scene.camera.position;
  Vec2 best(0.0f);
  float nearest = kInfinity;
  for (int py = 0; py < settings.height; ++py)
    for (int px = 0; px < settings.width; ++px) {
      const Ray ray = view.primaryRay(px + 0.5f, py + 0.5f);
      const Vec3 seen = eye + ray.direction * ((at.z - eye.z) / ray.direction.z);
      const float distance = glm::length(Vec2(seen.x - at.x, seen.y - at.y));
      if (distance < nearest) nearest = distance, best = Vec2(px, py);
    }
  return best;
}

// Two transparent squares, one in front of the other and offset, over an
// opaque one and over the background: the pixels where one, two or three
// overlap.
TEST(Transparency, StackedSquaresBlendAsTheFormulaSays) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0, 0, -8), 180, 120);
  scene.ambient = Color(0.8f);
  scene.materials.push_back(transparent(Color(0.9f, 0.3f, 0.2f), 0.6f));  // 1: red, in front
  scene.materials.push_back(transparent(Color(0.2f, 0.5f, 0.9f), 0.7f));  // 2: blue, behind
  addSquare(scene, 1.5f, 0.0f, 2.0f, 0);    // the opaque grey square, at the back, right
  addSquare(scene, 0.0f, 0.0f, 0.0f, 2);    // blue in the middle
  addSquare(scene, -0.8f, 0.3f, -1.0f, 1);  // red in front, left
  const Material& grey = scene.materials[0];
  const Material& red = scene.materials[1];
  const Material& blue = scene.materials[2];
  const Color background = scene.image.background;
  const Color greyLight = ownLight(scene, grey);
  const Color redLight = ownLight(scene, red), blueLight = ownLight(scene, blue);
  const RenderSettings settings = settingsFor(scene);
  struct Probe {
    Vec2 onBluePlane;
    Color expected;
  };
  const Probe probes[] = {
      {{-1.5f, 0.9f}, over(red, redLight, background)},
      {{-0.3f, 0.2f}, over(red, redLight, over(blue, blueLight, background))},
      {{0.8f, -0.5f}, over(blue, blueLight, greyLight)},
      {{0.2f, -0.9f}, over(blue, blueLight, background)},
      {{1.8f, 0.0f}, greyLight},
  };
  for (std::string_view algorithm : kBlendingAlgorithms) {
    const RenderResult result = render(algorithm, scene, settings);
    for (const Probe& probe : probes) {
      const Vec2 pixel = pixelSeeing(scene, settings, Vec3(probe.onBluePlane, 0.0f));
      expectNear(result.image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y)),
                 probe.expected, algorithm);
    }
  }
}

// Lit by a point light beside the camera, with Phong shading at every pixel
// and shadow maps, the blended squares are Whitted's image: the refracted
// rays go straight through (an index of refraction of 1) and are weighed as
// the blending weighs what is behind, and the shadow rays through a
// transparent square are filtered as the maps filter the light.
TEST(Transparency, MatchesTheRayTracerWhereNoRayBends) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(1, 1, -8), 120, 100);
  scene.ambient = Color(0.3f);
  scene.materials[0].kd = 0.7f;
  scene.materials.push_back(transparent(Color(0.9f, 0.6f, 0.2f), 0.5f));
  scene.materials[1].kd = 0.4f;
  scene.materials[1].ks = 0.5f;
  scene.materials[1].n = 20.0f;
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-3, 2, -6), Color(0.9f)));
  addSquare(scene, 0.5f, 0.0f, 1.5f, 0);
  addSquare(scene, -0.4f, 0.2f, 0.0f, 1);
  RenderSettings settings = settingsFor(scene);
  const RenderResult traced = render("ray-tracing", scene, settings);
  settings.shadows = ShadowMethod::Map;
  settings.shadowFilter = 0;
  for (std::string_view algorithm : kBlendingAlgorithms) {
    const RenderResult result = render(algorithm, scene, settings);
    int differing = 0;
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x) {
        const Color difference = glm::abs(result.image.at(x, y) - traced.image.at(x, y));
        differing += std::max({difference.r, difference.g, difference.b}) > 1e-3f;
      }
    // The shadow's edge on the grey square, a texel or so wide.
    EXPECT_LE(differing, 60) << algorithm;
  }
}

// The stack again, the red square now behind the blue one and the grey one
// in front of both, where it hides them: blended farthest first, and only
// what lies in front of the opaque surface.
TEST(Transparency, BlendsByDepthNotByDrawingOrder) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0, 0, -8), 150, 110);
  scene.ambient = Color(0.8f);
  scene.materials.push_back(transparent(Color(0.9f, 0.3f, 0.2f), 0.6f));  // 1: red, behind
  scene.materials.push_back(transparent(Color(0.2f, 0.5f, 0.9f), 0.7f));  // 2: blue, in front
  addSquare(scene, 0.0f, 0.0f, -1.0f, 2);                                 // blue, drawn first
  addSquare(scene, 0.2f, 0.1f, 1.0f, 1);
  addSquare(scene, 1.6f, 0.0f, -2.0f, 0);  // the opaque grey square, in front
  const Material& grey = scene.materials[0];
  const Material& red = scene.materials[1];
  const Material& blue = scene.materials[2];
  const Color background = scene.image.background;
  const RenderSettings settings = settingsFor(scene);
  // The middle of the squares shows blue over red over the background; the
  // grey square, in front of both where they overlap it, itself alone.
  const Color centre =
      over(blue, ownLight(scene, blue), over(red, ownLight(scene, red), background));
  const Vec2 throughBoth = pixelSeeing(scene, settings, Vec3(0.0f, 0.0f, -1.0f));
  const Vec2 onGrey = pixelSeeing(scene, settings, Vec3(1.0f, 0.0f, -2.0f));
  for (std::string_view algorithm : kBlendingAlgorithms) {
    const RenderResult result = render(algorithm, scene, settings);
    expectNear(result.image.at(static_cast<int>(throughBoth.x), static_cast<int>(throughBoth.y)),
               centre, algorithm);
    expectNear(result.image.at(static_cast<int>(onGrey.x), static_cast<int>(onGrey.y)),
               ownLight(scene, grey), algorithm);
  }
}

// The classic scene's glass sphere, at sizes and shapes other than the
// example's: the scanline algorithm blends it as the z-buffer does, within
// the examples' tolerance (a pixel in a hundred).
TEST(Transparency, TheGlassSphereLooksTheSameToTheScanlineAsToTheZBuffer) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  for (const auto& [width, height] : {std::pair{150, 61}, std::pair{53, 90}}) {
    RenderRequest request;
    request.image = {width, height, 1, SamplePattern::None, FilterKind::Box, {}};
    const RenderSettings settings = settingsFor(scene, request);
    const RenderResult scanline = render("scanline", scene, settings);
    EXPECT_GT(scanline.stats.value("transparent_blends"), 0.0);
    EXPECT_LE(
        raster_testing::pixelsDiffering(scanline.image, render("z-buffer", scene, settings).image),
        width * height / 100)
        << width << " x " << height;
  }
}

}  // namespace
}  // namespace rise
