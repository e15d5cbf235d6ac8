// What the transparency tests share: coloured transparent squares facing the
// camera, and the colour a stack of them shows, computed in the test as each
// surface's own light plus what is behind it filtered by its transmission
// times its colour.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/scene_file.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "support/raster_testing.hpp"

namespace rise::transparency_testing {

// A square of side 2 facing the camera (on -z) at depth z, centred at
// (x, y), of material `material`.
inline void addSquare(Scene& scene, float x, float y, float z, int material) {
  scene.shapes.push_back(std::make_unique<ConvexPolygon>(
      std::vector<Vec3>{{x - 1, y - 1, z}, {x + 1, y - 1, z}, {x + 1, y + 1, z}, {x - 1, y + 1, z}},
      material));
}

// A material lit by the ambient light alone that lets `transmission` of
// what is behind it through, tinted by its colour, and bends no ray.
inline Material transparent(const Color& color, float transmission) {
  Material material;
  material.color = color;
  material.ka = 1.0f;
  material.kd = 0.0f;
  material.transmission = transmission;
  material.ior = 1.0f;
  return material;
}

// Ambient light alone: each surface's own light is Ia ka C (1 - t).
inline Color ownLight(const Scene& scene, const Material& material) {
  return scene.ambient * material.ka * (1.0f - material.transmission) * material.color;
}

inline Color over(const Material& material, const Color& own, const Color& behind) {
  return own + material.transmission * material.color * behind;
}

inline void expectNear(const Color& seen, const Color& expected, std::string_view algorithm) {
  for (int channel = 0; channel < 3; ++channel)
    EXPECT_NEAR(seen[channel], expected[channel], 1e-5f) << algorithm << " channel " << channel;
}

// The pixel whose centre sees the point `at` of a plane facing the camera
// (z constant), or the nearest to it.
inline Vec2 pixelSeeing(const Scene& scene, const RenderSettings& settings, const Vec3& at) {
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

// The classic scene, whose glass sphere the visible-surface algorithms blend.
inline Scene classicScene() {
  return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
}

// The settings of `scene` at width x height, one sample a pixel at its centre.
inline RenderSettings settingsAtSize(const Scene& scene, int width, int height) {
  RenderRequest request;
  request.image = {width, height, 1, SamplePattern::None, FilterKind::Box, {}};
  return settingsFor(scene, request);
}

}  // namespace rise::transparency_testing
