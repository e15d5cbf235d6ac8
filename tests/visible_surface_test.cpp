// The four visible-surface algorithms against one another and against the ray
// tracer's primary rays: where no polygons interpenetrate, they must see the
// same face at every pixel (but for a few pixel centres lying on an edge,
// which rounding may give to either side) and the same surface as the rays.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/random.hpp"
#include "io/scene_file.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

Scene example(const std::string& name, int width, int height) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
  scene.image.width = width;
  scene.image.height = height;
  return scene;
}

void expectAllAgreeWithZBuffer(const Scene& scene, const RenderSettings& settings,
                               int allowedPixels) {
  const RenderResult reference = render("z-buffer", scene, settings);
  for (std::string_view algorithm : kAlgorithms) {
    const RenderResult result = render(algorithm, scene, settings);
    EXPECT_LE(pixelsSeeingOtherFaces(result, reference), allowedPixels) << algorithm;
  }
}

TEST(VisibleSurfaces, AgreeOnTheClassicScene) {
  const Scene scene = example("classic.yaml", 160, 120);
  expectAllAgreeWithZBuffer(scene, settingsFor(scene), 3);
}

TEST(VisibleSurfaces, AgreeOnTheSpheresScene) {
  const Scene scene = example("spheres.yaml", 160, 120);
  expectAllAgreeWithZBuffer(scene, settingsFor(scene), 3);
}

// The tessellated spheres, cylinder and cone differ from the true shapes along
// their outlines, by much less than a pixel at this tessellation; the floor,
// a square of kDefaultPlaneSize, reaches the horizon: all else is seen as the
// rays see it.
TEST(VisibleSurfaces, SeeTheExampleScenesAsTheRayTracerDoes) {
  for (const std::string name : {"classic.yaml", "spheres.yaml"}) {
    const Scene scene = example(name, 160, 120);
    RenderSettings settings = settingsFor(scene);
    settings.tessellation = 32;
    for (std::string_view algorithm : kAlgorithms) {
      const RenderResult result = render(algorithm, scene, settings);
      // Distances: the facets of a sphere lie inside it.
      EXPECT_LE(pixelsDisagreeingWithRays(scene, settings, result, 2e-3f), 3)
          << name << " " << algorithm;
    }
  }
}

bool interpenetrate(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  const auto edgeCrosses = [](const std::array<Vec3, 3>& edges, const std::array<Vec3, 3>& face) {
    for (int i = 0; i < 3; ++i) {
      const Ray edge{edges[i], edges[(i + 1) % 3] - edges[i]};
      float t;
      Vec2 barycentric;
      if (intersectTriangle(edge, face[0], face[1], face[2], 0.0f, 1.0f, t, barycentric))
        return true;
    }
    return false;
  };
  return edgeCrosses(a, b) || edgeCrosses(b, a);
}

// Triangles of random sizes, places and orientations, none piercing another:
// they overlap one another on the screen in every way, in front and behind.
Scene randomSoup(std::uint64_t seed, int count) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -6.0f), 120, 90);
  Rng rng(seed);
  const auto uniform = [&](float low, float high) { return low + (high - low) * rng.uniform(); };
  std::vector<std::array<Vec3, 3>> placed;
  while (static_cast<int>(placed.size()) < count) {
    const Vec3 centre(uniform(-1.5f, 1.5f), uniform(-1.0f, 1.0f), uniform(-1.5f, 1.5f));
    const float size = uniform(0.3f, 1.2f);
    std::array<Vec3, 3> triangle;
    for (Vec3& corner : triangle)
      corner =
          centre + size * Vec3(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
    if (std::any_of(placed.begin(), placed.end(),
                    [&](const auto& other) { return interpenetrate(triangle, other); }))
      continue;
    placed.push_back(triangle);
    addTriangle(scene, triangle[0], triangle[1], triangle[2]);
  }
  return scene;
}

TEST(VisibleSurfaces, AgreeOnRandomPolygonSoups) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const Scene scene = randomSoup(seed, 30);
    const RenderSettings settings = settingsFor(scene);
    expectAllAgreeWithZBuffer(scene, settings, 2);
    for (std::string_view algorithm : kAlgorithms)
      EXPECT_LE(pixelsDisagreeingWithRays(scene, settings, render(algorithm, scene, settings)), 2)
          << "seed " << seed << " " << algorithm;
  }
}

// Three long triangles, each lying over the next at one end and under the
// previous at the other, like three sticks dropped in a ring: no order of
// painting is right, and depth sort must split one to break the cycle.
Scene cyclicOverlap() {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -6.0f), 120, 120);
  for (int i = 0; i < 3; ++i) {
    const float angle = 2.0f * kPi * static_cast<float>(i) / 3.0f;
    const Vec3 along(std::cos(angle), std::sin(angle), 0.0f);
    const Vec3 across(-along.y, along.x, 0.0f);
    const Vec3 foot = 0.5f * across;
    // From its near end (z = -0.3) to its far one (z = 0.3).
    const Vec3 nearEnd = foot - 1.5f * along - Vec3(0.0f, 0.0f, 0.3f);
    const Vec3 farEnd = foot + 1.5f * along + Vec3(0.0f, 0.0f, 0.3f);
    addTriangle(scene, nearEnd - 0.3f * across, nearEnd + 0.3f * across, farEnd);
  }
  return scene;
}

TEST(VisibleSurfaces, DepthSortSplitsCyclicOverlaps) {
  const Scene scene = cyclicOverlap();
  const RenderSettings settings = settingsFor(scene);
  const RenderResult sorted = render("depth-sort", scene, settings);
  EXPECT_GT(sorted.stats.value("splits"), 0.0);
  EXPECT_EQ(sorted.stats.value("unresolved_overlaps"), 0.0);
  expectAllAgreeWithZBuffer(scene, settings, 2);
  EXPECT_LE(pixelsDisagreeingWithRays(scene, settings, sorted), 2);
}

// Two triangles crossing each other: each is in front on one side of the
// line where they meet.
Scene crossingTriangles() {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -6.0f), 120, 90);
  addTriangle(scene, Vec3(-1.5f, -1.0f, 0.0f), Vec3(1.5f, -1.0f, 0.0f), Vec3(0.0f, 1.2f, 0.0f));
  addTriangle(scene, Vec3(-1.5f, 0.0f, -1.0f), Vec3(1.5f, 0.2f, 1.0f), Vec3(0.0f, -1.2f, 0.2f));
  return scene;
}

TEST(VisibleSurfaces, DrawInterpenetratingPolygonsAsTheRaysSeeThem) {
  const Scene scene = crossingTriangles();
  const RenderSettings settings = settingsFor(scene);
  for (std::string_view algorithm : kAlgorithms) {
    const RenderResult result = render(algorithm, scene, settings);
    EXPECT_LE(pixelsDisagreeingWithRays(scene, settings, result), 2) << algorithm;
  }
  EXPECT_GT(render("depth-sort", scene, settings).stats.value("splits"), 0.0);
}

TEST(VisibleSurfaces, AreTheSameWhateverTheThreadCount) {
  const Scene scene = example("classic.yaml", 96, 72);
  RenderSettings settings = settingsFor(scene);
  for (std::string_view algorithm : kAlgorithms) {
    settings.threads = 1;
    const RenderResult one = render(algorithm, scene, settings);
    settings.threads = 3;
    const RenderResult three = render(algorithm, scene, settings);
    EXPECT_EQ(one.image.pixels(), three.image.pixels()) << algorithm;
    EXPECT_EQ(one.stats.value("pixels_written"), three.stats.value("pixels_written"));
  }
}

}  // namespace
}  // namespace rise
