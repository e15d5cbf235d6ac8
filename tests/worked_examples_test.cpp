// The manual's worked examples of a new algorithm (docs/examples/), built and
// rendered through the one door as the registry's algorithms are, so that the
// code a reader copies is code that works.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "eye_light.hpp"
#include "io/scene_file.hpp"
#include "render/render_limits.hpp"
#include "support/raster_testing.hpp"
#include "unsorted_painter.hpp"

namespace rise {
namespace {

using namespace raster_testing;

RenderResult renderWith(const Renderer& renderer, const Scene& scene) {
  const RenderSettings settings = settingsFor(scene);
  checkRenderFits(scene, settings, renderer);
  RenderObserver observer;
  return renderer.render(scene, settings, observer);
}

// A triangle facing the eye across the middle of the image, and one behind it.
Scene twoTrianglesOneBehindTheOther(int width, int height) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, 5.0f), width, height);
  Material red = scene.materials[0];
  red.color = Color(0.8f, 0.1f, 0.1f);
  scene.materials.push_back(red);
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 1);
  addTriangle(scene, Vec3(-2.0f, -2.0f, -1.0f), Vec3(2.0f, -2.0f, -1.0f), Vec3(0.0f, 2.0f, -1.0f));
  return scene;
}

// Whitted's tracer casts its primary rays in packets, whose arithmetic may
// round a distance differently in its last bit.
TEST(WorkedExamples, EyeLightSeesWhatWhittedsPrimaryRaysSee) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  scene.image.width = 96;
  scene.image.height = 72;
  const RenderResult eyeLight = renderWith(EyeLight{}, scene);
  const RenderResult whitted = render("ray-tracing", scene);
  const Image& depth = eyeLight.buffers.at("depth");
  const Image& expected = whitted.buffers.at("depth");
  for (int y = 0; y < depth.height(); ++y)
    for (int x = 0; x < depth.width(); ++x) {
      const float seen = depth.at(x, y).r, expectedSeen = expected.at(x, y).r;
      ASSERT_TRUE(seen == expectedSeen || std::abs(seen - expectedSeen) <= 1e-4f * expectedSeen)
          << x << ", " << y << ": " << seen << " where Whitted's tracer sees " << expectedSeen;
    }
  EXPECT_EQ(eyeLight.stats.value("primary_rays"), 96.0 * 72.0);
}

TEST(WorkedExamples, EyeLightShadesASurfaceFacingTheEyeInItsOwnColour) {
  const Scene scene = twoTrianglesOneBehindTheOther(41, 31);
  const Color centre = renderWith(EyeLight{}, scene).image.at(20, 15);
  EXPECT_NEAR(centre.r, 0.8f, 1e-3f);
  EXPECT_NEAR(centre.g, 0.1f, 1e-3f);
}

TEST(WorkedExamples, UnsortedPainterLetsTheLastPolygonMadeCoverTheNearest) {
  const Scene scene = twoTrianglesOneBehindTheOther(41, 31);
  const RenderResult painted = renderWith(UnsortedPainter{}, scene);
  const RenderResult zBuffer = render("z-buffer", scene);
  EXPECT_EQ(faceAt(zBuffer, 20, 15), 0);
  EXPECT_EQ(faceAt(painted, 20, 15), 1);
  EXPECT_GT(pixelsSeeingOtherFaces(painted, zBuffer), 100);
  EXPECT_GT(painted.stats.value("pixels_written"), 41.0 * 31.0 / 4.0);
}

}  // namespace
}  // namespace rise
