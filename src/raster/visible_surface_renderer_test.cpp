#include "raster/visible_surface_renderer.hpp"

#include <gtest/gtest.h>

#include "algorithms/registry.hpp"
#include "scene/light.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/sphere.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using raster_testing::addTriangle;
using raster_testing::sceneSeenFrom;

void expectTheSameToTheBit(const ScreenGeometry& actual, const ScreenGeometry& expected) {
  ASSERT_EQ(actual.corners.size(), expected.corners.size());
  for (std::size_t i = 0; i < actual.corners.size(); ++i)
    ASSERT_EQ(actual.corners[i], expected.corners[i]) << "corner " << i;
  ASSERT_EQ(actual.faces.size(), expected.faces.size());
  for (std::size_t i = 0; i < actual.faces.size(); ++i) {
    const ScreenFace& a = actual.faces[i];
    const ScreenFace& e = expected.faces[i];
    ASSERT_EQ(a.sceneFace, e.sceneFace) << "face " << i;
    ASSERT_EQ(a.frontFacing, e.frontFacing) << "face " << i;
    ASSERT_EQ(a.origin, e.origin) << "face " << i;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a.weights[k].coefficients, e.weights[k].coefficients);
    ASSERT_EQ(a.inverseDepth.coefficients, e.inverseDepth.coefficients) << "face " << i;
  }
  ASSERT_EQ(actual.polygons.size(), expected.polygons.size());
  for (std::size_t i = 0; i < actual.polygons.size(); ++i) {
    ASSERT_EQ(actual.polygons[i].face, expected.polygons[i].face);
    ASSERT_EQ(actual.polygons[i].firstCorner, expected.polygons[i].firstCorner);
    ASSERT_EQ(actual.polygons[i].cornerCount, expected.polygons[i].cornerCount);
  }
}

// The passes that see the scene from one point of the lens share one
// projection, each moving it by its own shift in the pixel; what each pass
// is given is still what projecting the scene for it alone gives, to the
// bit, through a pinhole (every pass shares) and through a lens (none does).
// The box and a triangle that the sides of the image cut make polygons that
// clipping shapes.
TEST(PassProjections, GiveEachPassWhatProjectingForItAloneGives) {
  Scene scene = sceneSeenFrom(Vec3(2.0f, 3.0f, -6.0f), 72, 40);
  scene.shapes.push_back(std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f), 0));
  addTriangle(scene, Vec3(-30.0f, -1.0f, -2.0f), Vec3(30.0f, -1.0f, -2.0f),
              Vec3(0.0f, -1.0f, 40.0f));
  for (float aperture : {0.0f, 0.3f}) {
    scene.camera.aperture = aperture;
    scene.camera.focalDistance = 6.0f;
    RenderRequest request;
    request.image = {72, 40, 6, SamplePattern::Jittered, FilterKind::Box, {}};
    const RenderSettings settings = settingsFor(scene, request);
    const std::vector<AccumulationPass> passes = accumulationPasses(scene.camera, settings);
    const TessellatedScene tessellated = tessellateForRaster(scene, settings);
    const ViewFrame frame(scene.camera, settings.width, settings.height);
    const Workers workers(2);
    PassProjections projections(frame, passes, true, workers);
    std::vector<ScreenGeometry> given;
    for (int pass = 0; pass < static_cast<int>(passes.size()); ++pass) {
      SCOPED_TRACE("aperture " + std::to_string(aperture) + ", pass " + std::to_string(pass));
      const ViewProjection view(frame, passes[pass].pixelOffset, passes[pass].lens);
      ASSERT_NE(view.shift(), Vec2(0.0f));
      const ScreenGeometry shared = projections.of(pass, tessellated);
      expectTheSameToTheBit(shared, projectScene(tessellated, view, true, workers));
      given.push_back(shared);
    }
    // The passes' projections differ: each was moved by its own shift.
    ASSERT_FALSE(given[0].corners.empty());
    EXPECT_NE(given[0].corners[0], given[1].corners[0]);
  }
}

// A render's time is split into the shadows, the visible surfaces, the
// shading and the rest; lights cost the shading, not the visible surfaces.
TEST(RenderTime, IsSplitIntoVisibleSurfacesAndShadingAsTheirWorkIs) {
#ifdef RISE_SANITIZED_BUILD
  GTEST_SKIP() << "the sanitizers' checks change what each part of a render costs";
#endif
  Scene scene = sceneSeenFrom(Vec3(2.0f, 3.0f, -6.0f), 320, 240);
  scene.materials[0].kd = 0.5f;
  scene.materials[0].ks = 0.5f;
  for (int x = -3; x <= 3; ++x)
    for (int z = -3; z <= 3; ++z)
      scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.3f * x, 0.0f, 0.3f * z), 0.15f, 0));
  RenderRequest request;
  // Finely tessellated, so that Gouraud's shading has many vertices to light.
  request.settings.tessellation = 24;
  const auto split = [&](int lights) {
    scene.lights.clear();
    for (int l = 0; l < lights; ++l)
      scene.lights.push_back(std::make_unique<PointLight>(
          Vec3(0.25f * static_cast<float>(l) - 8.0f, 5.0f, -4.0f), Color(0.01f)));
    RenderObserver observer;
    return renderTimed(*findRenderer("z-buffer"), scene, settingsFor(scene, request), observer)
        .stats;
  };
  // Phong's shading lights each pixel; Gouraud's each vertex, before drawing.
  for (const Shading shading : {Shading::Phong, Shading::Gouraud}) {
    SCOPED_TRACE(std::string(shadingName(shading)));
    request.settings.shading = shading;
    const Stats unlit = split(0), lit = split(64);
    for (const Stats& stats : {unlit, lit}) {
      EXPECT_GT(stats.value("visible_surface_seconds"), 0.0);
      EXPECT_GT(stats.value("shading_seconds"), 0.0);
      EXPECT_LE(stats.value("visible_surface_seconds") + stats.value("shading_seconds"),
                stats.value("render_seconds"));
    }
    EXPECT_GT(lit.value("shading_seconds"), 2.0 * unlit.value("shading_seconds"));
    EXPECT_GT(lit.value("shading_seconds") - unlit.value("shading_seconds"),
              lit.value("visible_surface_seconds") - unlit.value("visible_surface_seconds"));
  }
}

}  // namespace
}  // namespace rise
