// What the tests of the hybrid algorithm share: scenes of random spheres,
// boxes and meshes, mirrors and glass among them, and the comparison of its
// image with another, pixel by pixel, telling the pixels inside an object
// from those on an outline.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "core/random.hpp"
#include "io/byte_encoding.hpp"
#include "scene/light.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/raster_testing.hpp"

namespace rise::hybrid_testing {

enum RandomMaterial { kFloor, kRed, kBlue, kMirror, kGlass, kMaterialCount };

inline std::vector<Material> randomSceneMaterials() {
  std::vector<Material> materials(kMaterialCount);
  materials[kFloor].color = Color(0.8f);
  materials[kFloor].kd = 0.8f;
  materials[kFloor].ks = 0.0f;
  materials[kRed].color = Color(0.9f, 0.1f, 0.1f);
  materials[kBlue].color = Color(0.2f, 0.3f, 0.9f);
  for (RandomMaterial matte : {kRed, kBlue}) {
    materials[matte].kd = 0.7f;
    materials[matte].ks = 0.3f;
    materials[matte].n = 32.0f;
  }
  materials[kMirror].color = Color(0.9f);
  materials[kMirror].kd = 0.1f;
  materials[kMirror].ks = 0.9f;
  materials[kMirror].n = 200.0f;
  materials[kMirror].reflection = 0.8f;
  materials[kGlass].color = Color(1.0f);
  materials[kGlass].kd = 0.0f;
  materials[kGlass].ks = 0.9f;
  materials[kGlass].n = 200.0f;
  materials[kGlass].transmission = 0.9f;
  materials[kGlass].ior = 1.5f;
  for (Material& material : materials) material.ka = 0.1f;
  return materials;
}

inline Vec3 randomPoint(Rng& rng, const Vec3& low, const Vec3& high) {
  return low + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (high - low);
}

// An octahedron or an icosahedron of flat triangles, placed by `placement`.
inline std::unique_ptr<Shape> polyhedron(bool icosahedron, const Mat4& placement, int material) {
  const float g = 1.618034f;
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  if (icosahedron) {
    vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  } else {
    vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    triangles = {{0, 2, 4}, {4, 2, 1}, {1, 2, 5}, {5, 2, 0},
                 {4, 3, 0}, {1, 3, 4}, {5, 3, 1}, {0, 3, 5}};
  }
  for (Vec3& vertex : vertices) vertex = Vec3(placement * glm::vec4(vertex, 1.0f));
  return std::make_unique<TriangleMesh>(std::move(vertices), std::move(triangles), material);
}

// A floor, two lights and `objects` spheres, boxes (turned) and meshes at
// random, some of them touching or cutting into others, each of a random
// material among matte, mirror and glass; the camera above, looking down at
// them.
inline Scene randomScene(std::uint64_t seed, int width, int height, int objects = 12) {
  Rng rng(seed);
  Scene scene = raster_testing::sceneSeenFrom(
      randomPoint(rng, Vec3(-2.0f, 1.5f, -7.0f), Vec3(2.0f, 3.5f, -5.0f)), width, height);
  scene.camera.lookAt = Vec3(0.0f, 0.6f, 1.0f);
  scene.camera.fovDegrees = 35.0f + 15.0f * rng.uniform();
  scene.ambient = Color(0.1f);
  scene.materials = randomSceneMaterials();
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-4.0f, 6.0f, -4.0f), Color(1.0f)));
  scene.lights.push_back(std::make_unique<DirectionalLight>(Vec3(1.0f, -1.0f, 0.5f), Color(0.3f)));
  scene.shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), kFloor));
  for (int i = 0; i < objects; ++i) {
    const int material = 1 + static_cast<int>(rng.below(kMaterialCount - 1));
    const Vec3 centre = randomPoint(rng, Vec3(-3.0f, 0.0f, -1.0f), Vec3(3.0f, 1.5f, 4.0f));
    const float size = 0.3f + 0.7f * rng.uniform();
    const Mat4 placement = glm::scale(
        glm::rotate(
            glm::translate(Mat4(1.0f), centre), 6.3f * rng.uniform(),
            glm::normalize(randomPoint(rng, Vec3(-1.0f), Vec3(1.0f)) + Vec3(0.0f, 0.01f, 0.0f))),
        Vec3(size));
    switch (rng.below(5)) {
      case 0:
      case 1:
        scene.shapes.push_back(std::make_unique<Sphere>(centre, size, material));
        break;
      case 2:
        scene.shapes.push_back(std::make_unique<TransformedShape>(
            std::make_unique<Box>(Vec3(-0.5f), Vec3(0.5f), material), placement));
        break;
      default:
        scene.shapes.push_back(polyhedron(rng.below(2) == 0, placement, material));
    }
  }
  return scene;
}

// How an image compares with another: the pixels whose 8-bit sRGB values
// differ by more than 2 levels in some channel, and those of them inside an
// object, where the item buffer shows the same object at the pixel and at its
// eight neighbours.
struct Agreement {
  int differing = 0;
  int differingInside = 0;
};

inline bool differs(const Color& a, const Color& b) {
  for (int channel = 0; channel < 3; ++channel)
    if (std::abs(byteFromLinear(a[channel], Encoding::Srgb) -
                 byteFromLinear(b[channel], Encoding::Srgb)) > 2)
      return true;
  return false;
}

inline Agreement compareImages(const Scene& scene, const RenderSettings& settings,
                               const RenderResult& hybrid, const Image& expected) {
  const TessellatedScene tessellated = tessellateForRaster(scene, settings);
  const auto objectAt = [&](int x, int y) {
    const int face = raster_testing::faceAt(hybrid, x, y);
    return face < 0 ? -1 : tessellated.faces[static_cast<std::size_t>(face)].shape;
  };
  const auto inside = [&](int x, int y) {
    const int object = objectAt(x, y);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = std::clamp(x + dx, 0, settings.width - 1);
        const int ny = std::clamp(y + dy, 0, settings.height - 1);
        if (objectAt(nx, ny) != object) return false;
      }
    return object >= 0;
  };
  Agreement agreement;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x)
      if (differs(hybrid.image.at(x, y), expected.at(x, y))) {
        ++agreement.differing;
        agreement.differingInside += inside(x, y) ? 1 : 0;
      }
  return agreement;
}

}  // namespace rise::hybrid_testing
