// Every acceleration structure gives the answers of brute force: the same
// nearest hit (t to the bit, shape and primitive) and the same transmittance,
// for many random rays, at random instants of the shutter interval, through
// random scenes of every kind of shape, moving ones too.
#include "ray/accelerator.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <stdexcept>

#include "ray/scene_intersector.hpp"
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

namespace rise {
namespace {

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

// How the packets of the two tests below are made: of every size in turn,
// every other one coherent, every third from a tMin above zero.
struct PacketPlan {
  int size;
  bool coherent;
  float tMin;
};
PacketPlan packetPlan(int packet, RandomScene& rays, float largestTMin) {
  return {1 + packet % kPacketSize, packet % 2 == 0,
          packet % 3 == 0 ? rays.uniform(0.0f, largestTMin) : 0.0f};
}

// Packets of every size: coherent ones (rays from one point to neighbouring
// points, as a row of pixels' primary rays) and scattered ones, with rays
// ended early and rays of non-finite components among them. Each ray of a
// packet finds what it finds alone, to the bit: what brute force finds
// (above).
TEST(Accelerators, FindEachRayOfAPacketsNearestHit) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  forEachSceneAndStructure(3000, [&](const Scene& scene, int seed, Accel accel, RandomScene& rays) {
    const auto structure = buildAccelerator(accel, scene.shapes);
    int hits = 0;
    for (int i = 0; i < kRaysPerScene / kPacketSize; ++i) {
      const PacketPlan plan = packetPlan(i, rays, 0.3f);
      const Vec3 eye = rays.point(7.0f), aim = rays.point(4.0f);
      RayPacket packet;
      packet.size = plan.size;
      for (int lane = 0; lane < packet.size; ++lane) {
        packet.rays[lane] = plan.coherent
                                ? Ray{eye, aim + 0.05f * Vec3(lane % 4, lane / 4, 0) - eye, 0.5f}
                                : rays.ray();
        if (i % 7 == 0 && lane == 2) packet.rays[lane].direction.y = nan;
        packet.hits[lane].t = lane % 3 == 1 ? rays.uniform(0.2f, 1.0f) : kInfinity;
      }
      const RayPacket given = packet;
      structure->nearestOfPacket(packet, plan.tMin);
      for (int lane = 0; lane < packet.size; ++lane) {
        Hit expected = given.hits[lane];
        IntersectionCounters counters;
        const bool found = structure->nearest(given.rays[lane], plan.tMin, expected, counters);
        ASSERT_EQ(packet.found[lane], found)
            << accelName(accel) << ", scene " << seed << ", packet " << i << ", lane " << lane;
        if (!found) continue;
        ++hits;
        const Hit& actual = packet.hits[lane];
        ASSERT_EQ(actual.t, expected.t) << accelName(accel) << ", packet " << i;
        ASSERT_EQ(actual.shape, expected.shape) << accelName(accel) << ", packet " << i;
        // A shape records only what it needs (a sphere leaves the rest as it found it).
        if (expected.shape->primitiveCount() > 1) {
          EXPECT_EQ(actual.primitive, expected.primitive) << accelName(accel) << ", packet " << i;
          EXPECT_EQ(actual.barycentric, expected.barycentric) << accelName(accel);
        }
      }
    }
    EXPECT_GT(hits, kRaysPerScene / 6) << accelName(accel);
  });
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

// Packets of shadow rays of every size: coherent ones (from neighbouring
// points towards one light) and scattered ones, of different lengths, with
// rays of non-finite components among them. Each ray of a packet lets
// through what it lets through alone, to the bit, and its tests are its own.
TEST(Accelerators, LetThroughEachRayOfAPacketsLightAsAlone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  forEachSceneAndStructure(4000, [&](const Scene& scene, int seed, Accel accel, RandomScene& rays) {
    const SceneIntersector intersector(scene, accel);
    int shadowed = 0;
    int filtered = 0;
    for (int i = 0; i < kRaysPerScene / kPacketSize; ++i) {
      const PacketPlan plan = packetPlan(i, rays, 0.1f);
      const Vec3 start = rays.point(4.0f), light = rays.point(7.0f);
      ShadowRayPacket packet;
      packet.size = plan.size;
      for (int lane = 0; lane < packet.size; ++lane) {
        const Vec3 from = start + 0.05f * Vec3(lane % 4, lane / 4, 0);
        packet.rays[lane] = plan.coherent ? Ray{from, light - from, 0.5f} : rays.ray();
        if (i % 7 == 0 && lane == 2) packet.rays[lane].origin.x = nan;
        packet.tMax[lane] = plan.coherent && lane % 3 != 1 ? 1.0f : rays.uniform(0.2f, 1.2f);
      }
      const ShadowRayPacket given = packet;
      const std::array<Color, kPacketSize> through =
          intersector.transmittanceOfPacket(packet, plan.tMin);
      for (int lane = 0; lane < packet.size; ++lane) {
        IntersectionCounters alone;
        const Color expected =
            intersector.transmittance(given.rays[lane], plan.tMin, given.tMax[lane], alone);
        ASSERT_EQ(through[lane], expected)
            << accelName(accel) << ", scene " << seed << ", packet " << i << ", lane " << lane;
        EXPECT_EQ(packet.costs[lane].tests > 0, alone.tests > 0) << accelName(accel);
        if (expected == Color(0.0f)) ++shadowed;
        if (expected != Color(0.0f) && expected != Color(1.0f)) ++filtered;
      }
    }
    EXPECT_GT(shadowed, kRaysPerScene / 10) << accelName(accel);
    EXPECT_GT(filtered, kRaysPerScene / 40) << accelName(accel);
  });
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
