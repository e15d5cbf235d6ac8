#include "raster/scanline.hpp"

#include <gtest/gtest.h>

#include "support/raster_testing.hpp"

namespace rise {
namespace {

using namespace raster_testing;

Scene oneTriangle(int width, int height) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), width, height);
  addTriangle(scene, Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.2f, -0.2f, 0.0f), Vec3(0.1f, 1.1f, 0.0f));
  return scene;
}

RenderResult renderOnOneThread(const Scene& scene) {
  RenderSettings settings = settingsFor(scene);
  settings.threads = 1;
  return render("scanline", scene, settings);
}

// Dreux's point: a depth and a face for each pixel of one scanline, however
// many scanlines the image has.
TEST(Scanline, NeedsBuffersAsWideAsTheImageNotAsLarge) {
  const double narrow = renderOnOneThread(oneTriangle(64, 48)).stats.value("scanline_buffer_bytes");
  EXPECT_EQ(narrow, 64.0 * 8.0);
  EXPECT_EQ(renderOnOneThread(oneTriangle(64, 480)).stats.value("scanline_buffer_bytes"), narrow);
  EXPECT_EQ(renderOnOneThread(oneTriangle(128, 48)).stats.value("scanline_buffer_bytes"),
            2.0 * narrow);
}

// A triangle with no horizontal edge puts its three edges in the edge table,
// and two of them are active on every scanline it crosses. (An image one band
// high: each band has an edge table of its own.)
TEST(Scanline, KeepsTwoActiveEdgesForATriangle) {
  const Scene scene = oneTriangle(48, 16);
  const RenderResult result = renderOnOneThread(scene);
  EXPECT_EQ(result.stats.value("edge_table_entries"), 3.0);
  EXPECT_EQ(result.stats.value("active_edges_max"), 2.0);
  EXPECT_GT(result.stats.value("active_edges_per_scanline"), 1.0);
  EXPECT_EQ(pixelsDisagreeingWithRays(scene, settingsFor(scene), result), 0);
}

// The two triangles of a square share an edge: its crossings, computed the
// same way for both, give each pixel to exactly one of them.
TEST(Scanline, DrawsEachPixelOfAMeshOnce) {
  Scene scene = sceneSeenFrom(Vec3(0.0f, 0.0f, -5.0f), 40, 30);
  const Vec3 a(-1.0f, -1.0f, 0.0f), b(1.0f, -0.7f, 0.0f), c(0.8f, 1.0f, 0.0f), d(-1.1f, 0.9f, 0.0f);
  addTriangle(scene, a, c, b);
  addTriangle(scene, a, d, c);
  const RenderResult result = renderOnOneThread(scene);
  EXPECT_EQ(result.stats.value("overdraw"), 1.0);
  EXPECT_EQ(pixelsSeeingOtherFaces(result, render("z-buffer", scene)), 0);
}

// The "cost" buffer charges each pixel the depth tests made at it: two where
// a triangle lies over another, one where it lies alone. The tests are
// counted alike whether the buffer is wanted or not.
TEST(Scanline, ChargesEachPixelItsDepthTests) {
  Scene scene = oneTriangle(48, 40);
  addTriangle(scene, Vec3(-0.6f, -0.8f, -0.5f), Vec3(0.9f, -0.6f, -0.5f), Vec3(0.0f, 0.7f, -0.5f));
  RenderSettings settings = settingsFor(scene);
  settings.buffers = std::vector<std::string>{};
  const double unwantedTests = render("scanline", scene, settings).stats.value("depth_tests");
  settings.buffers = std::vector<std::string>{"cost"};
  const RenderResult result = render("scanline", scene, settings);
  const Image& cost = result.buffers.at("cost");
  double charged = 0.0;
  int overlapped = 0;
  for (int y = 0; y < cost.height(); ++y)
    for (int x = 0; x < cost.width(); ++x) {
      charged += cost.at(x, y).r;
      overlapped += cost.at(x, y).r == 2.0f;
    }
  EXPECT_EQ(charged, result.stats.value("depth_tests"));
  EXPECT_EQ(unwantedTests, result.stats.value("depth_tests"));
  EXPECT_GT(overlapped, 100);
}

}  // namespace
}  // namespace rise
