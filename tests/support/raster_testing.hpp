// What the tests of the visible-surface algorithms share: small scenes built
// in code, renders by algorithm name, and comparisons of what renders, or the
// ray tracer's primary rays, see at each pixel.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string_view>
#include <vector>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "raster/visible_surface_renderer.hpp"
#include "scene/shapes/triangle.hpp"

namespace rise::raster_testing {

// The names of the visible-surface algorithms, from the registry.
inline std::vector<std::string_view> visibleSurfaceAlgorithms() {
  std::vector<std::string_view> names;
  for (const Renderer* renderer : allRenderers())
    if (renderer->description().family == Family::VisibleSurface) names.push_back(renderer->name());
  return names;
}
inline const std::vector<std::string_view> kAlgorithms = visibleSurfaceAlgorithms();

// An empty scene seen from `eye`, looking at the origin, with one matte grey
// material (number 0) and ambient light alone, so that every pixel of a
// material has one colour.
inline Scene sceneSeenFrom(const Vec3& eye, int width, int height) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.image.background = Color(0.1f, 0.2f, 0.3f);
  scene.camera.position = eye;
  scene.camera.lookAt = Vec3(0.0f);
  scene.camera.fovDegrees = 40.0f;
  scene.ambient = Color(1.0f);
  Material matte;
  matte.color = Color(0.5f);
  matte.ka = 1.0f;
  scene.materials.push_back(matte);
  return scene;
}

inline void addTriangle(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c,
                        int material = 0) {
  scene.shapes.push_back(std::make_unique<Triangle>(std::array{a, b, c}, material));
}

inline RenderResult render(std::string_view algorithm, const Scene& scene,
                           const RenderSettings& settings) {
  RenderObserver observer;
  return findRenderer(algorithm)->render(scene, settings, observer);
}

inline RenderResult render(std::string_view algorithm, const Scene& scene) {
  return render(algorithm, scene, settingsFor(scene));
}

inline int faceAt(const RenderResult& result, int x, int y) {
  return static_cast<int>(result.buffers.at("face").at(x, y).r);
}

// The pixels at which two renders see different faces.
inline int pixelsSeeingOtherFaces(const RenderResult& a, const RenderResult& b) {
  const Image& faces = a.buffers.at("face");
  int differing = 0;
  for (int y = 0; y < faces.height(); ++y)
    for (int x = 0; x < faces.width(); ++x) differing += faceAt(a, x, y) != faceAt(b, x, y);
  return differing;
}

// The pixels at which two images differ by more than 0.02 in a channel.
inline int pixelsDiffering(const Image& a, const Image& b) {
  int differing = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      differing += glm::any(glm::greaterThan(glm::abs(a.at(x, y) - b.at(x, y)), Color(0.02f)));
  return differing;
}

// What the ray tracer's primary ray through a pixel's centre meets first:
// the shape's number (-1 for none) and how far away.
struct PrimaryHit {
  int shape = -1;
  float distance = kInfinity;
};

inline PrimaryHit primaryHit(const Scene& scene, const ViewFrame& view, int x, int y) {
  const Ray ray = view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
  Hit hit;
  IntersectionCounters counters;
  PrimaryHit nearest;
  for (std::size_t shape = 0; shape < scene.shapes.size(); ++shape)
    if (scene.shapes[shape]->intersect(ray, 0.0f, hit, counters))
      nearest = {static_cast<int>(shape), hit.t};
  return nearest;
}

// The pixels at which a raster render sees another shape than the primary
// ray does, or sees it at another distance (relative tolerance).
inline int pixelsDisagreeingWithRays(const Scene& scene, const RenderSettings& settings,
                                     const RenderResult& result, float distanceTolerance = 1e-3f) {
  const TessellatedScene tessellated = tessellateForRaster(scene, settings);
  const ViewFrame view(scene.camera, settings.width, settings.height);
  int disagreeing = 0;
  for (int y = 0; y < settings.height; ++y) {
    for (int x = 0; x < settings.width; ++x) {
      const PrimaryHit hit = primaryHit(scene, view, x, y);
      const int face = faceAt(result, x, y);
      const int shape = face < 0 ? -1 : tessellated.faces[face].shape;
      const float distance = result.buffers.at("depth").at(x, y).r;
      const bool sameShape = shape == hit.shape;
      const bool sameDistance =
          shape < 0 || std::abs(distance - hit.distance) <= distanceTolerance * hit.distance;
      disagreeing += !(sameShape && sameDistance);
    }
  }
  return disagreeing;
}

}  // namespace rise::raster_testing
