// The z-buffer's and the scanline's shadow maps against Whitted's shadow
// rays: at each pixel, the surface the primary ray meets is in shadow when a
// light in front of it does not wholly reach it along a shadow ray; the
// raster image is in shadow where it is darker than the same render without
// shadows. The two masks must agree but for a few pixels, and those only
// near an edge of a shadow or of a shape, where the map's texels and the
// tessellation's facets may put the edge a pixel to either side, and where
// percentage-closer filtering darkens a ramp a texel or two wide.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_file.hpp"
#include "ray/scene_intersector.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using raster_testing::render;

// What the rays see at each pixel: the shape met (-1 for none), and whether a
// light in front of it is blocked, wholly or in part (-1: a surface without
// diffuse light, which shadows cannot darken in the raster image).
struct RayMasks {
  std::vector<int> shape;
  std::vector<int> shadowed;
};

RayMasks shadowRayMasks(const Scene& scene, int width, int height) {
  const SceneIntersector intersector(scene, Accel::Bvh, 1);
  const ViewFrame view(scene.camera, width, height);
  IntersectionCounters counters;
  RayMasks masks{std::vector<int>(static_cast<std::size_t>(width) * height, -1),
                 std::vector<int>(static_cast<std::size_t>(width) * height, -1)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Ray ray = view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      Hit hit;
      if (!intersector.nearest(ray, 0.0f, hit, counters)) continue;
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      for (std::size_t s = 0; s < scene.shapes.size(); ++s)
        if (scene.shapes[s].get() == hit.shape) masks.shape[pixel] = static_cast<int>(s);
      if (scene.materials[hit.shape->material()].kd == 0.0f) continue;
      const SurfacePoint surface = hit.shape->surfaceAt(ray, hit);
      const Vec3 normal =
          glm::dot(surface.normal, ray.direction) > 0.0f ? -surface.normal : surface.normal;
      int blocked = 0;
      for (const auto& light : scene.lights) {
        const LightSample sample = light->illuminate(surface.position);
        if (glm::dot(normal, sample.toLight) <= 0.0f) continue;
        const Ray shadowRay{surface.position + 1e-4f * normal, sample.toLight, 0.0f};
        blocked |=
            intersector.transmittance(shadowRay, 0.0f, sample.distance, counters) != Color(1.0f);
      }
      masks.shadowed[pixel] = blocked;
    }
  return masks;
}

// Whether a mask or the shape seen changes within two pixels of (x, y).
bool nearAnEdge(const RayMasks& masks, int width, int height, int x, int y) {
  const std::size_t here = static_cast<std::size_t>(y) * width + x;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
      const std::size_t there = static_cast<std::size_t>(ny) * width + nx;
      if (masks.shape[there] != masks.shape[here] || masks.shadowed[there] != masks.shadowed[here])
        return true;
    }
  return false;
}

struct Disagreement {
  int pixels = 0;         // where the map and the rays disagree
  int awayFromEdges = 0;  // of those, more than two pixels from any edge
  int shadowed = 0;       // where the rays see a shadow
};

Disagreement againstShadowRays(const Scene& scene, std::string_view algorithm,
                               RenderSettings settings) {
  settings.tessellation = 32;
  settings.shadows = ShadowMethod::None;
  const RenderResult unshadowed = render(algorithm, scene, settings);
  settings.shadows = ShadowMethod::Map;
  const RenderResult shadowed = render(algorithm, scene, settings);
  const RayMasks masks = shadowRayMasks(scene, settings.width, settings.height);
  Disagreement found;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const int byRays = masks.shadowed[static_cast<std::size_t>(y) * settings.width + x];
      if (byRays < 0) continue;
      const Color lit = unshadowed.image.at(x, y), dimmed = shadowed.image.at(x, y);
      const bool byMap = dimmed.r + dimmed.g + dimmed.b < lit.r + lit.g + lit.b - 1e-5f;
      found.shadowed += byRays;
      if (byMap == (byRays == 1)) continue;
      ++found.pixels;
      found.awayFromEdges += !nearAnEdge(masks, settings.width, settings.height, x, y);
    }
  return found;
}

Scene example(const std::string& name, int width, int height) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  scene.image.width = width;
  scene.image.height = height;
  return scene;
}

// The classic scene: a point and a directional light, shadows of spheres,
// a box, a cylinder and a cone on the floor and on one another, and the
// glass sphere's, lighter.
TEST(ShadowMaps, AgreeWithShadowRaysOnTheClassicScene) {
  const Scene scene = example("classic.yaml", 200, 150);
  for (std::string_view algorithm : {"z-buffer", "scanline"}) {
    const Disagreement found = againstShadowRays(scene, algorithm, settingsFor(scene));
    EXPECT_GT(found.shadowed, 1000) << algorithm;
    EXPECT_LE(found.pixels, 80) << algorithm;
    EXPECT_LE(found.awayFromEdges, 2) << algorithm;
  }
}

// A ball over a plane, wide and low, lit from the side by a point light,
// with a smaller map: a long shadow, foreshortened.
TEST(ShadowMaps, AgreeWithShadowRaysOnABallOverAPlane) {
  const Scene scene = loadScene(R"(
image: {width: 240, height: 90}
camera: {position: [0, 3, -7], look_at: [0, 0.5, 0], fov: 35}
ambient: [0.2, 0.2, 0.2]
lights:
  - point: {position: [-5, 3.5, 1], color: [1, 1, 1]}
materials:
  matte: {color: [0.7, 0.7, 0.6], ka: 0.2, kd: 0.8}
objects:
  - plane:  {point: [0, 0, 0], normal: [0, 1, 0], material: matte}
  - sphere: {center: [0, 1.2, 0], radius: 0.8, material: matte}
)",
                                "ball.yaml");
  RenderSettings settings = settingsFor(scene);
  settings.shadowMapSize = 512;
  const Disagreement found = againstShadowRays(scene, "z-buffer", settings);
  EXPECT_GT(found.shadowed, 1500);
  EXPECT_LE(found.pixels, 120);
  EXPECT_LE(found.awayFromEdges, 2);
}

}  // namespace
}  // namespace rise
