#include "raster/z_buffer.hpp"

#include <gtest/gtest.h>

#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

// A square of two triangles facing the camera at z = 0, seen from z = -5.
Scene squareOfTwoTriangles() {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  const Vec3 a(-1.0f, -1.0f, 0.0f), b(1.0f, -1.0f, 0.0f), c(1.0f, 1.0f, 0.0f), d(-1.0f, 1.0f, 0.0f);
  addTriangle(scene, a, c, b);
  addTriangle(scene, a, d, c);
  return scene;
}

int coveredPixels(const RenderResult& result) {
  int covered = 0;
  for (const Color& face : result.buffers.at("face").pixels()) covered += face.r >= 0.0f;
  return covered;
}

// The shared diagonal's pixels go to one triangle or the other, never both.
TEST(ZBuffer, DrawsEachPixelOfAMeshOnce) {
  const RenderResult result = render("z-buffer", squareOfTwoTriangles());
  EXPECT_GT(coveredPixels(result), 200);
  EXPECT_EQ(result.stats.value("pixels_written"), coveredPixels(result));
  EXPECT_EQ(result.stats.value("depth_tests"), coveredPixels(result));
  EXPECT_EQ(result.stats.value("overdraw"), 1.0);
}

// The depth buffer holds the distance along the primary ray, as the ray
// tracer's does: 5 / cos of the ray's angle to the view direction here.
TEST(ZBuffer, StoresTheDistanceAlongTheEyeRay) {
  const Scene scene = squareOfTwoTriangles();
  const RenderResult result = render("z-buffer", scene);
  const ViewFrame frame(scene.camera, 40, 30);
  for (const auto& [x, y] : {std::pair{20, 15}, std::pair{14, 10}, std::pair{25, 19}}) {
    const Ray ray = frame.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    EXPECT_NEAR(result.buffers.at("depth").at(x, y).r, 5.0f / ray.direction.z, 1e-4f);
  }
}

// Two overlapping triangles, drawn in either order: the nearer one wins, and
// where they overlap each pixel takes two depth tests.
TEST(ZBuffer, KeepsTheNearerSurfaceInEitherOrder) {
  for (bool nearerFirst : {true, false}) {
    Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
    const auto addNear = [&] {
      addTriangle(scene, Vec3(-1.0f, -1.0f, -1.0f), Vec3(1.0f, -1.0f, -1.0f),
                  Vec3(0.0f, 1.0f, -1.0f));
    };
    const auto addFar = [&] {
      addTriangle(scene, Vec3(-2.0f, 1.0f, 1.0f), Vec3(2.0f, 1.0f, 1.0f), Vec3(0.0f, -2.0f, 1.0f));
    };
    if (nearerFirst) {
      addNear();
      addFar();
    } else {
      addFar();
      addNear();
    }
    const RenderResult result = render("z-buffer", scene);
    // The middle of the image sees the near triangle, 4 away.
    EXPECT_NEAR(result.buffers.at("depth").at(20, 15).r, 4.0f, 0.01f);
    EXPECT_EQ(result.buffers.at("cost").at(20, 15).r, 2.0f);
    EXPECT_EQ(pixelsDisagreeingWithRays(scene, settingsFor(scene), result), 0);
  }
}

TEST(ZBuffer, NeedsADepthAndAFaceForEveryPixel) {
  const RenderResult result = render("z-buffer", squareOfTwoTriangles());
  EXPECT_EQ(result.stats.value("z_buffer_bytes"), 40.0 * 30.0 * 8.0);
}

}  // namespace
}  // namespace rise
