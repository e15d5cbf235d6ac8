// Every acceleration structure gives the answers of brute force: the same
// nearest hit (t to the bit, shape and primitive) and the same transmittance,
// for many random rays, at random instants of the shutter interval, through
// random scenes of every kind of shape, moving ones too.
#include "ray/accelerator.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "ray/scene_intersector.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/random_scene_testing.hpp"

namespace rise {
namespace {

using namespace random_scene_testing;

TEST(Accelerators, FindTheNearestHitOfBruteForce) {
  for (int seed = 0; seed < kScenes; ++seed) {
    RandomScene random(seed);
    const Scene scene = random.scene();
    const auto bruteForce = buildAccelerator(Accel::None, scene.shapes);
    for (Accel accel : availableAccels()) {
      const auto structure = buildAccelerator(accel, scene.shapes);
      RandomScene rays(1000 + seed);
      int hits = 0;
      for (int i = 0; i < kRaysPerScene; ++i) {
        const Ray ray = rays.ray();
        // Half the rays end before infinity, as a nearer hit already found ends them.
        const float tMax = i % 2 == 0 ? kInfinity : rays.uniform(0.2f, 1.0f);
        const float tMin = i % 3 == 0 ? rays.uniform(0.0f, 0.3f) : 0.0f;
        Hit expected, actual;
        expected.t = actual.t = tMax;
        IntersectionCounters counters;
        const bool found = bruteForce->nearest(ray, tMin, expected, counters);
        ASSERT_EQ(structure->nearest(ray, tMin, actual, counters), found)
            << accelName(accel) << ", scene " << seed << ", ray " << i;
        if (!found) continue;
        ++hits;
        ASSERT_EQ(actual.t, expected.t) << accelName(accel) << ", scene " << seed << ", ray " << i;
        ASSERT_EQ(actual.shape, expected.shape) << accelName(accel) << ", ray " << i;
        // A shape records only what it needs (a sphere leaves the primitive
        // as it found it): the triangle of a mesh, and the surface.
        if (expected.shape->primitiveCount() > 1) {
          EXPECT_EQ(actual.primitive, expected.primitive) << accelName(accel) << ", ray " << i;
        }
        const SurfacePoint expectedSurface = expected.shape->surfaceAt(ray, expected);
        const SurfacePoint actualSurface = actual.shape->surfaceAt(ray, actual);
        EXPECT_EQ(actualSurface.position, expectedSurface.position) << accelName(accel);
        EXPECT_EQ(actualSurface.normal, expectedSurface.normal) << accelName(accel);
        EXPECT_EQ(actualSurface.uv, expectedSurface.uv) << accelName(accel);
      }
      EXPECT_GT(hits, kRaysPerScene / 3) << accelName(accel);
    }
  }
}

TEST(Accelerators, LetThroughTheLightOfBruteForce) {
  for (int seed = 0; seed < kScenes; ++seed) {
    RandomScene random(seed);
    const Scene scene = random.scene();
    const SceneIntersector bruteForce(scene, Accel::None);
    for (Accel accel : availableAccels()) {
      const SceneIntersector intersector(scene, accel);
      RandomScene rays(2000 + seed);
      int shadowed = 0;
      int filtered = 0;
      for (int i = 0; i < kRaysPerScene; ++i) {
        const Ray ray = rays.ray();
        const float tMax = rays.uniform(0.3f, 1.2f);
        IntersectionCounters counters;
        const Color expected = bruteForce.transmittance(ray, 0.0f, tMax, counters);
        const Color actual = intersector.transmittance(ray, 0.0f, tMax, counters);
        ASSERT_EQ(actual, expected) << accelName(accel) << ", scene " << seed << ", ray " << i;
        if (expected == Color(0.0f)) ++shadowed;
        if (expected != Color(0.0f) && expected != Color(1.0f)) ++filtered;
      }
      EXPECT_GT(shadowed, kRaysPerScene / 10) << accelName(accel);
      EXPECT_GT(filtered, kRaysPerScene / 20) << accelName(accel);
    }
  }
}

// Two parallel squares, one mesh of four triangles, both crossed by the
// ray along z through (0.1, 0.1).
std::unique_ptr<Shape> twoSquares(int material) {
  return std::make_unique<TriangleMesh>(
      std::vector<Vec3>{{-2, -2, -1},
                        {2, -2, -1},
                        {2, 2, -1},
                        {-2, 2, -1},
                        {-2, -2, 1},
                        {2, -2, 1},
                        {2, 2, 1},
                        {-2, 2, 1}},
      std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, material);
}

// Glass filters a shadow ray once per shape, however many of a mesh's
// triangles the ray crosses: the mesh's two squares and a sphere filter it
// twice, not three times; an opaque mesh blocks it.
TEST(Accelerators, FilterOncePerShapeCrossed) {
  Scene scene;
  scene.materials.resize(3);
  scene.materials[kTintedGlass].transmission = 0.5f;
  scene.materials[kTintedGlass].color = Color(0.8f, 0.6f, 0.4f);
  scene.shapes.push_back(twoSquares(kTintedGlass));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f, 0.0f, 4.0f), 1.0f, kTintedGlass));
  const Ray ray{{0.1f, 0.1f, -5.0f}, {0.0f, 0.0f, 1.0f}};
  const Color once = 0.5f * Color(0.8f, 0.6f, 0.4f);
  for (Accel accel : availableAccels()) {
    const SceneIntersector intersector(scene, accel);
    IntersectionCounters counters;
    EXPECT_EQ(intersector.transmittance(ray, 0.0f, 20.0f, counters), once * once)
        << accelName(accel);
  }
  scene.shapes[0] = twoSquares(kOpaque);
  for (Accel accel : availableAccels()) {
    const SceneIntersector intersector(scene, accel);
    IntersectionCounters counters;
    EXPECT_EQ(intersector.transmittance(ray, 0.0f, 20.0f, counters), Color(0.0f))
        << accelName(accel);
  }
}

// A square of two triangles, split along its diagonal; `flipped` lists
// them the other way round.
std::unique_ptr<Shape> splitSquare(bool flipped) {
  std::vector<std::array<int, 3>> faces{{0, 1, 2}, {0, 2, 3}};
  if (flipped) std::swap(faces[0], faces[1]);
  return std::make_unique<TriangleMesh>(
      std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, std::move(faces), kOpaque);
}

// A ray through the diagonal meets both triangles at the same t. Brute force
// keeps the first in the mesh's order; the BVH too, whichever it tests
// first. (Embree keeps the one its own traversal meets first.)
TEST(Accelerators, BreakTiesAsBruteForceDoes) {
  const Ray throughDiagonal{{0.25f, 0.25f, -1.0f}, {0.0f, 0.0f, 1.0f}};
  for (bool flipped : {false, true}) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(splitSquare(flipped));
    shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), kOpaque));
    for (Accel accel : {Accel::None, Accel::Spheres, Accel::Bvh}) {
      Hit hit;
      IntersectionCounters counters;
      ASSERT_TRUE(buildAccelerator(accel, shapes)->nearest(throughDiagonal, 0.0f, hit, counters));
      EXPECT_EQ(hit.t, 1.0f);
      EXPECT_EQ(hit.shape, shapes[0].get()) << accelName(accel) << ": the plane is second";
      EXPECT_EQ(hit.primitive, 0) << accelName(accel) << (flipped ? ", flipped" : "");
    }
  }
}

// A NaN or infinite ray, as a shading routine gone wrong could make, meets
// nothing: every box test would otherwise take it to meet every box.
TEST(Accelerators, AreSafeAgainstARayOfNonFiniteComponents) {
  RandomScene random(0);
  const Scene scene = random.scene();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<Ray> rays{{{0, 0, -20}, {nan, 0, 1}},       {{nan, 0, -20}, {0, 0, 1}},
                              {{0, 0, -20}, {kInfinity, 0, 1}}, {{0, -kInfinity, 0}, {0, 1, 0}},
                              {{0, 0, -20}, {nan, nan, nan}},   {{0, 0, -20}, {0, 0, -kInfinity}}};
  for (Accel accel : availableAccels()) {
    const SceneIntersector intersector(scene, accel);
    const auto structure = buildAccelerator(accel, scene.shapes);
    for (const Ray& ray : rays) {
      Hit hit;
      IntersectionCounters counters;
      EXPECT_FALSE(structure->nearest(ray, 0.0f, hit, counters)) << accelName(accel);
      EXPECT_EQ(intersector.transmittance(ray, 0.0f, 100.0f, counters), Color(1.0f))
          << accelName(accel);
    }
  }
}

TEST(Accelerators, AreNamedAsOnTheCommandLine) {
  std::vector<std::string_view> names;
  for (Accel accel : kAllAccels) names.push_back(accelName(accel));
  EXPECT_EQ(names, (std::vector<std::string_view>{"none", "spheres", "bvh", "embree"}));
  EXPECT_TRUE(isAvailable(Accel::None));
  EXPECT_TRUE(isAvailable(Accel::Spheres));
  EXPECT_TRUE(isAvailable(Accel::Bvh));
}

TEST(Accelerators, RefuseOneThisBuildLacks) {
  if (isAvailable(Accel::Embree)) GTEST_SKIP() << "this build has Embree";
  const std::vector<std::unique_ptr<Shape>> shapes;
  EXPECT_THROW(buildAccelerator(Accel::Embree, shapes), std::invalid_argument);
}

}  // namespace
}  // namespace rise
