// Random scenes of every kind of shape, moving ones too, in materials opaque,
// clear and tinted, and random rays through them: what the tests of the
// acceleration structures (src/ray/accelerator*_test.cpp) hold every
// structure against brute force with.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "ray/accelerator.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/keyframed_mesh.hpp"
#include "scene/shapes/moving_shape.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/transform.hpp"

namespace rise::random_scene_testing {

constexpr int kOpaque = 0;
constexpr int kGlass = 1;
constexpr int kTintedGlass = 2;

class RandomScene {
 public:
  explicit RandomScene(unsigned seed) : random_(seed) {}

  float uniform(float low, float high) {
    return std::uniform_real_distribution<float>(low, high)(random_);
  }
  Vec3 point(float extent) {
    return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
  }
  int material() { return std::uniform_int_distribution<int>(0, 2)(random_); }

  // Small triangles scattered through the cube of half-width `extent`.
  std::unique_ptr<Shape> triangleSoup(int triangles, float extent) {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> faces;
    for (int i = 0; i < triangles; ++i) {
      const Vec3 centre = point(extent);
      const int first = static_cast<int>(vertices.size());
      for (int corner = 0; corner < 3; ++corner) vertices.push_back(centre + point(0.4f));
      faces.push_back({first, first + 1, first + 2});
    }
    return std::make_unique<TriangleMesh>(std::move(vertices), std::move(faces), material());
  }

  // A closed mesh: a grid of quads wrapped around a sphere, whose triangles
  // share edges and vertices, as a modelled mesh does.
  static MeshGeometry closedMeshGeometry(Vec3 centre, float radius) {
    constexpr int kRings = 8;
    constexpr int kSegments = 12;
    std::vector<Vec3> vertices;
    for (int ring = 0; ring <= kRings; ++ring) {
      const float polar = kPi * static_cast<float>(ring) / kRings;
      for (int segment = 0; segment < kSegments; ++segment) {
        const float azimuth = 2.0f * kPi * static_cast<float>(segment) / kSegments;
        vertices.push_back(centre + radius * Vec3(std::sin(polar) * std::cos(azimuth),
                                                  std::cos(polar),
                                                  std::sin(polar) * std::sin(azimuth)));
      }
    }
    std::vector<std::array<int, 3>> faces;
    for (int ring = 0; ring < kRings; ++ring) {
      for (int segment = 0; segment < kSegments; ++segment) {
        const int a = ring * kSegments + segment;
        const int b = ring * kSegments + (segment + 1) % kSegments;
        faces.push_back({a, b, a + kSegments});
        faces.push_back({b, b + kSegments, a + kSegments});
      }
    }
    return {std::move(vertices), {}, {}, std::move(faces)};
  }
  std::unique_ptr<Shape> closedMesh(Vec3 centre, float radius) {
    return std::make_unique<TriangleMesh>(closedMeshGeometry(centre, radius), material());
  }

  // Shapes that move while the shutter is open: rays of different times
  // meet them in different places.
  std::unique_ptr<Shape> movingBox() {
    const Vec3 start = point(3.0f);
    return std::make_unique<MovingShape>(
        std::make_unique<Box>(Vec3(-0.4f), Vec3(0.4f), material()),
        TransformSpec{.translate = start},
        TransformSpec{.rotateDegrees = point(90.0f), .translate = start + point(1.0f)});
  }
  std::unique_ptr<Shape> keyframedMesh() {
    const Vec3 start = point(3.0f);
    return std::make_unique<KeyframedMesh>(
        closedMeshGeometry(start, 0.8f), closedMeshGeometry(start + point(1.0f), 1.1f), material());
  }

  std::unique_ptr<Shape> turned(std::unique_ptr<Shape> shape) {
    return std::make_unique<TransformedShape>(std::move(shape),
                                              worldFromObject({.scale = Vec3(uniform(0.5f, 1.5f)),
                                                               .rotateDegrees = point(180.0f),
                                                               .translate = point(3.0f)}));
  }

  Scene scene() {
    Scene scene;
    scene.materials.resize(3);
    scene.materials[kGlass].transmission = 0.9f;
    scene.materials[kTintedGlass].transmission = 0.5f;
    scene.materials[kTintedGlass].color = Color(0.9f, 0.6f, 0.3f);
    auto& shapes = scene.shapes;
    shapes.push_back(std::make_unique<Plane>(Vec3(0.0f, -5.0f, 0.0f), Vec3(0.1f, 1.0f, 0.0f), 0));
    shapes.push_back(triangleSoup(300, 4.0f));
    shapes.push_back(closedMesh(point(3.0f), 1.2f));
    shapes.push_back(turned(closedMesh(Vec3(0.0f), 1.0f)));
    shapes.push_back(turned(triangleSoup(50, 1.0f)));
    shapes.push_back(movingBox());
    shapes.push_back(keyframedMesh());
    for (int i = 0; i < 6; ++i) {
      shapes.push_back(std::make_unique<Sphere>(point(4.0f), uniform(0.2f, 1.0f), material()));
      const Vec3 corner = point(4.0f);
      shapes.push_back(std::make_unique<Box>(corner, corner + point(0.8f), material()));
      shapes.push_back(std::make_unique<Cylinder>(point(4.0f), point(1.0f), uniform(0.1f, 0.6f),
                                                  uniform(0.3f, 1.5f), material()));
      shapes.push_back(std::make_unique<Cone>(point(4.0f), point(1.0f), uniform(0.1f, 0.6f),
                                              uniform(0.3f, 1.5f), material()));
      shapes.push_back(std::make_unique<Triangle>(
          std::array<Vec3, 3>{point(4.0f), point(4.0f), point(4.0f)}, material()));
      shapes.push_back(turned(std::make_unique<Box>(Vec3(-0.5f), Vec3(0.5f), material())));
    }
    const Vec3 base = point(3.0f);
    shapes.push_back(std::make_unique<ConvexPolygon>(
        std::vector<Vec3>{base, base + Vec3(1.0f, 0.0f, 0.2f), base + Vec3(1.0f, 1.0f, 0.2f),
                          base + Vec3(0.0f, 1.0f, 0.0f)},
        material()));
    return scene;
  }

  // From anywhere around the scene towards anywhere in it.
  Ray ray() {
    const Vec3 origin = point(7.0f);
    return Ray{origin, point(4.0f) - origin, uniform(0.0f, 1.0f)};
  }

 private:
  std::mt19937 random_;
};

constexpr int kScenes = 4;
constexpr int kRaysPerScene = 3000;

// Calls test(scene, its seed, structure, rays) for each random scene and
// each structure this build has, `rays` drawing from a seed of its own
// (raySeed plus the scene's).
template <typename Test>
void forEachSceneAndStructure(int raySeed, Test&& test) {
  for (int seed = 0; seed < kScenes; ++seed) {
    RandomScene random(seed);
    const Scene scene = random.scene();
    for (Accel accel : availableAccels()) {
      RandomScene rays(raySeed + seed);
      test(scene, seed, accel, rays);
    }
  }
}

}  // namespace rise::random_scene_testing
