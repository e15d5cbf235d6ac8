// What the tests of shading at a first hit share (Whitted's Shade in two
// halves, a batch of first hits): a scene where every part of Shade is at
// work, a floor, a mirror, glass and an opaque sphere in a light's way,
// under two lights.
#pragma once

#include <memory>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"

namespace rise::first_hit_testing {

inline Scene mirrorGlassAndBlockerScene(int width, int height) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.camera.position = {0.0f, 1.0f, -5.0f};
  scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
  scene.camera.fovDegrees = 50.0f;
  scene.ambient = Color(0.2f);
  Material matte;
  matte.kd = 0.7f;
  matte.ks = 0.3f;
  Material mirror = matte;
  mirror.reflection = 0.5f;
  Material glass = matte;
  glass.transmission = 0.8f;
  glass.color = {0.7f, 0.9f, 1.0f};
  glass.ior = 1.5f;
  scene.materials = {matte, mirror, glass};
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 0));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(-1.0f, 0.0f, 0.5f), 0.8f, 1));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(1.0f, -0.3f, -0.5f), 0.6f, 2));
  // The blocker, between the first light and the floor.
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.3f, 1.5f, 0.0f), 0.4f, 0));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(1.0f, 4.0f, -2.0f), Color(0.8f)));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-4.0f, 2.0f, -1.0f), Color(0.4f)));
  return scene;
}

}  // namespace rise::first_hit_testing
