// Transparency in depth sort, area subdivision, the z-buffer and the scanline
// algorithm:
// coloured transparent squares stacked over a background and over an opaque
// square give the colour a formula in the test computes, each surface's own
// light plus what is behind it filtered by its transmission times its colour;
// with an index of refraction of 1, which bends no ray, the same image as
// Whitted's ray tracer, shadows through the squares included; and the glass
// sphere of the classic scene looks the same to all four. The z-buffer
// blends both ways: sorted, and by Carpenter's A-buffer (a_buffer_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "support/raster_testing.hpp"
#include "support/transparency_testing.hpp"

namespace rise {
namespace {

using raster_testing::render;
using namespace transparency_testing;

// The algorithms that blend, the z-buffer both ways.
struct Blender {
  std::string_view algorithm;
  Transparency transparency;
  std::string_view label;
};
constexpr Blender kBlenders[] = {
    {"depth-sort", Transparency::Sorted, "depth-sort"},
    {"area-subdivision", Transparency::Sorted, "area-subdivision"},
    {"z-buffer", Transparency::Sorted, "z-buffer"},
    {"z-buffer", Transparency::ABuffer, "z-buffer --transparency a-buffer"},
    {"scanline", Transparency::Sorted, "scanline"},
};

RenderResult render(const Blender& blender, const Scene& scene, RenderSettings settings) {
  settings.transparency = blender.transparency;
  return render(blender.algorithm, scene, settings);
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
  for (const Blender& blender : kBlenders) {
    const RenderResult result = render(blender, scene, settings);
    for (const Probe& probe : probes) {
      const Vec2 pixel = pixelSeeing(scene, settings, Vec3(probe.onBluePlane, 0.0f));
      expectNear(result.image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y)),
                 probe.expected, blender.label);
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
  for (const Blender& blender : kBlenders) {
    const RenderResult result = render(blender, scene, settings);
    int differing = 0;
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x) {
        const Color difference = glm::abs(result.image.at(x, y) - traced.image.at(x, y));
        differing += std::max({difference.r, difference.g, difference.b}) > 1e-3f;
      }
    // The shadow's edge on the grey square, a texel or so wide.
    EXPECT_LE(differing, 60) << blender.label;
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
  for (const Blender& blender : kBlenders) {
    const RenderResult result = render(blender, scene, settings);
    expectNear(result.image.at(static_cast<int>(throughBoth.x), static_cast<int>(throughBoth.y)),
               centre, blender.label);
    expectNear(result.image.at(static_cast<int>(onGrey.x), static_cast<int>(onGrey.y)),
               ownLight(scene, grey), blender.label);
  }
}

// The classic scene's glass sphere, at sizes and shapes other than the
// example's: the scanline algorithm and area subdivision blend it as the
// z-buffer does, within the examples' tolerance (a pixel in a hundred).
TEST(Transparency, TheGlassSphereLooksTheSameToEveryBlenderAsToTheZBuffer) {
  const Scene scene = classicScene();
  for (const auto& [width, height] : {std::pair{150, 61}, std::pair{53, 90}}) {
    const RenderSettings settings = settingsAtSize(scene, width, height);
    const Image zBuffer = render("z-buffer", scene, settings).image;
    for (const std::string_view algorithm : {"scanline", "area-subdivision"}) {
      const RenderResult blended = render(algorithm, scene, settings);
      EXPECT_GT(blended.stats.value("transparent_blends"), 0.0) << algorithm;
      EXPECT_LE(raster_testing::pixelsDiffering(blended.image, zBuffer), width * height / 100)
          << algorithm << " at " << width << " x " << height;
    }
  }
}

}  // namespace
}  // namespace rise
