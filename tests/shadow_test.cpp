// The z-buffer's and the scanline's shadow maps, and the scanline's shadow
// volumes, against Whitted's shadow rays: at each pixel, the surface the
// primary ray meets is in shadow when a light in front of it does not wholly
// reach it along a shadow ray; the raster image is in shadow where it is
// darker than the same render without shadows. With maps the two masks must
// agree but for a few pixels, and those only near an edge of a shadow or of a
// shape, where the map's texels and the tessellation's facets may put the
// edge a pixel to either side, and where percentage-closer filtering darkens
// a ramp a texel or two wide. Shadow volumes do not sample: away from those
// edges they disagree at a few pixels of a scene, where the facets of a
// tessellated surface meet a smooth one's shadow (on a scene of flat shapes,
// whose polygons are the shapes themselves, at none).
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
                               RenderSettings settings, ShadowMethod method = ShadowMethod::Map) {
  settings.tessellation = 32;
  settings.shadows = ShadowMethod::None;
  const RenderResult unshadowed = render(algorithm, scene, settings);
  settings.shadows = method;
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

// A ball over a plane, wide and low, lit from the side by a point light: a
// long shadow, foreshortened.
Scene ballOverAPlane() {
  return loadScene(R"(
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
}

// With a smaller map.
TEST(ShadowMaps, AgreeWithShadowRaysOnABallOverAPlane) {
  const Scene scene = ballOverAPlane();
  RenderSettings settings = settingsFor(scene);
  settings.shadowMapSize = 512;
  const Disagreement found = againstShadowRays(scene, "z-buffer", settings);
  EXPECT_GT(found.shadowed, 1500);
  EXPECT_LE(found.pixels, 120);
  EXPECT_LE(found.awayFromEdges, 2);
}

// Shadow volumes: a scene of opaque shapes at a size and shape of its own.
Scene opaqueShapes(const std::string& lights, int width, int height) {
  Scene scene = loadScene(R"(
camera: {position: [1, 2.5, -6], look_at: [0, 0.6, 0], fov: 45}
ambient: [0.2, 0.2, 0.2]
lights: [)" + lights + R"(]
materials:
  matte: {color: [0.7, 0.7, 0.6], ka: 0.2, kd: 0.8}
  shiny: {color: [0.8, 0.2, 0.2], ka: 0.1, kd: 0.6, ks: 0.4, n: 30}
objects:
  - plane:    {point: [0, 0, 0], normal: [0, 1, 0], material: matte}
  - sphere:   {center: [-1.2, 0.8, 0.5], radius: 0.8, material: shiny}
  - box:      {min: [0.5, 0, -0.5], max: [1.5, 1.2, 0.5], material: matte}
  - cylinder: {base: [-0.3, 0, -1.8], axis: [0, 1, 0], radius: 0.3, height: 1.2, material: shiny}
  - cone:     {base: [1.8, 0, -1.6], axis: [0, 1, 0], radius: 0.4, height: 1.0, material: matte}
  - triangle: {vertices: [[-2, 1.6, 1.5], [-0.5, 1.9, 1.5], [-1.2, 2.6, 2.2]], material: shiny}
)",
                          "shapes.yaml");
  scene.image.width = width;
  scene.image.height = height;
  return scene;
}

TEST(ShadowVolumes, AgreeWithShadowRaysAwayFromEdgesUnderAPointLight) {
  const Scene scene = opaqueShapes("{point: {position: [-3, 5, -3], color: [1, 1, 1]}}", 157, 203);
  const Disagreement found =
      againstShadowRays(scene, "scanline", settingsFor(scene), ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 1800);
  EXPECT_LE(found.pixels, 400);
  EXPECT_LE(found.awayFromEdges, 25);
}

TEST(ShadowVolumes, AgreeWithShadowRaysAwayFromEdgesOnABallOverAPlane) {
  const Scene scene = ballOverAPlane();
  const Disagreement found =
      againstShadowRays(scene, "scanline", settingsFor(scene), ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 1500);
  EXPECT_LE(found.awayFromEdges, 2);
}

// Where every shape is its own polygons (boxes, a polygon, a triangle, a
// mesh, the floor), the volumes are the shadows' exact shapes: the two
// masks disagree only at the pixels an edge passes through.
TEST(ShadowVolumes, AgreeWithShadowRaysExactlyAwayFromEdgesWhereTheShapesAreFlat) {
  Scene scene = loadScene(R"(
camera: {position: [-1.5, 3, -6.5], look_at: [0.3, 0.5, 0], fov: 45}
ambient: [0.2, 0.2, 0.2]
lights:
  - point: {position: [-3, 5, -3], color: [0.7, 0.7, 0.7]}
  - directional: {direction: [1, -1.5, 0.7], color: [0.4, 0.4, 0.4]}
materials:
  matte: {color: [0.7, 0.7, 0.6], ka: 0.2, kd: 0.8}
  shiny: {color: [0.8, 0.2, 0.2], ka: 0.1, kd: 0.6, ks: 0.4, n: 30}
objects:
  - plane:    {point: [0, 0, 0], normal: [0, 1, 0], material: matte}
  - box:      {min: [0.5, 0, -0.5], max: [1.5, 1.2, 0.5], material: shiny}
  - box:      {min: [-1.6, 0.9, -0.4], max: [-0.4, 1.1, 0.8], material: matte}
  - box:      {min: [-1.3, 0, 0], max: [-1.1, 0.9, 0.2], material: matte}
  - polygon:  {vertices: [[-2.5, 0, 2], [-1, 0, 2], [-1, 1.8, 2.2], [-2.5, 1.8, 2.2]], material: matte}
  - triangle: {vertices: [[0, 1.6, 1.5], [1.5, 1.9, 1.5], [0.8, 2.6, 2.2]], material: shiny}
  - mesh:
      vertices: [[0, 1, -1.5], [0.5, 0.5, -1.5], [0, 0.5, -1], [-0.5, 0.5, -1.5], [0, 0.5, -2], [0, 0, -1.5]]
      faces: [[0, 2, 1], [0, 3, 2], [0, 4, 3], [0, 1, 4], [5, 1, 2], [5, 2, 3], [5, 3, 4], [5, 4, 1]]
      material: shiny
)",
                          "flat.yaml");
  scene.image.width = 173;
  scene.image.height = 141;
  const Disagreement found =
      againstShadowRays(scene, "scanline", settingsFor(scene), ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 800);
  EXPECT_EQ(found.awayFromEdges, 0);
}

// A directional light and a point light together, each with its volumes.
TEST(ShadowVolumes, AgreeWithShadowRaysUnderADirectionalLight) {
  const Scene scene = opaqueShapes(
      "{directional: {direction: [1, -1.5, 0.7], color: [0.6, 0.6, 0.6]}}, "
      "{point: {position: [3, 4, -2], color: [0.5, 0.5, 0.5]}}",
      230, 120);
  const Disagreement found =
      againstShadowRays(scene, "scanline", settingsFor(scene), ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 1400);
  EXPECT_LE(found.awayFromEdges, 15);
}

// The eye stands in the shadow of a roof it does not see: every count starts
// at 1, and the floor around it is in shadow though no volume's face lies
// between them.
TEST(ShadowVolumes, CountFromTheVolumesTheEyeIsIn) {
  const Scene scene = loadScene(R"(
image: {width: 120, height: 160}
camera: {position: [0, 1, -4], look_at: [0, 0.3, 0], fov: 50}
ambient: [0.2, 0.2, 0.2]
lights:
  - point: {position: [0, 6, -4], color: [1, 1, 1]}
materials:
  matte: {color: [0.7, 0.7, 0.6], ka: 0.2, kd: 0.8}
objects:
  - plane:  {point: [0, 0, 0], normal: [0, 1, 0], material: matte}
  - box:    {min: [-2, 3, -6], max: [2, 3.2, -2], material: matte}
  - sphere: {center: [0.5, 0.5, 1.5], radius: 0.5, material: matte}
)",
                                "roof.yaml");
  RenderSettings settings = settingsFor(scene);
  settings.shadows = ShadowMethod::Volume;
  EXPECT_EQ(render("scanline", scene, settings).stats.value("eye_in_volumes"), 1.0);
  const Disagreement found = againstShadowRays(scene, "scanline", settings, ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 3000);
  EXPECT_LE(found.awayFromEdges, 2);
}

// The classic scene with its glass made opaque (a count says in or out, not
// how much light gets through), at a size of its own.
TEST(ShadowVolumes, AgreeWithShadowRaysOnTheClassicSceneWithoutGlass) {
  Scene scene = example("classic.yaml", 210, 130);
  for (Material& material : scene.materials) material.transmission = 0.0f;
  const Disagreement found =
      againstShadowRays(scene, "scanline", settingsFor(scene), ShadowMethod::Volume);
  EXPECT_GT(found.shadowed, 800);
  EXPECT_LE(found.awayFromEdges, 12);
}

}  // namespace
}  // namespace rise
