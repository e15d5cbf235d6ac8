#include "raster/view_projection.hpp"

#include <gtest/gtest.h>

namespace rise {
namespace {

Camera obliqueCamera() {
  Camera camera;
  camera.position = {1.0f, 2.0f, -5.0f};
  camera.lookAt = {-0.5f, 0.3f, 1.0f};
  camera.up = {0.1f, 1.0f, 0.0f};
  camera.fovDegrees = 55.0f;
  return camera;
}

// A point the ray tracer's primary ray through (x, y) meets projects back to
// (x, y): rays and projection agree.
TEST(ViewProjection, ProjectsPointsOnAPrimaryRayToItsRasterPosition) {
  const ViewFrame frame(obliqueCamera(), 320, 200);
  const ViewProjection view(frame);
  for (const Vec2 raster : {Vec2(0.5f, 0.5f), Vec2(160.0f, 100.0f), Vec2(317.25f, 13.5f)}) {
    const Ray ray = frame.primaryRay(raster.x, raster.y);
    for (float t : {0.5f, 3.0f, 40.0f}) {
      const Vec3 camera = view.toCamera(ray.at(t));
      const Vec2 projected = view.toRaster(camera);
      EXPECT_NEAR(projected.x, raster.x, 1e-3f);
      EXPECT_NEAR(projected.y, raster.y, 1e-3f);
      // n is the distance along the view direction.
      EXPECT_NEAR(camera.z, t * glm::dot(ray.direction, frame.forward()), 1e-4f * t);
    }
  }
}

TEST(ViewProjection, IsTheReportsMatrixOfUVNRowsAfterTheTranslation) {
  const ViewFrame frame(obliqueCamera(), 320, 200);
  const ViewProjection view(frame);
  const Vec3 point(0.7f, -1.1f, 2.3f);
  const Vec3 offset = point - frame.eye();
  const Vec3 expected(glm::dot(offset, frame.right()), glm::dot(offset, frame.up()),
                      glm::dot(offset, frame.forward()));
  const Vec3 camera = view.toCamera(point);
  EXPECT_NEAR(camera.x, expected.x, 1e-5f);
  EXPECT_NEAR(camera.y, expected.y, 1e-5f);
  EXPECT_NEAR(camera.z, expected.z, 1e-5f);
}

// With the sample offset (0.25, 0.75), the point that the ray through
// (i + 0.25, j + 0.75) meets lands on pixel (i, j)'s centre.
TEST(ViewProjection, ShiftsTheImageSoThatTheSampleLandsOnThePixelCentre) {
  const ViewFrame frame(obliqueCamera(), 64, 48);
  const ViewProjection view(frame, Vec2(0.25f, 0.75f));
  const Vec3 point = frame.primaryRay(10.25f, 20.75f).at(4.0f);
  const Vec2 projected = view.toRaster(view.toCamera(point));
  EXPECT_NEAR(projected.x, 10.5f, 1e-4f);
  EXPECT_NEAR(projected.y, 20.5f, 1e-4f);
  const Vec3 direction = view.cameraDirection(projected);
  const Vec3 camera = view.toCamera(point);
  EXPECT_NEAR(direction.x, camera.x / camera.z, 1e-5f);
  EXPECT_NEAR(direction.y, camera.y / camera.z, 1e-5f);
}

TEST(ViewProjection, BoundsTheViewVolumeByTheNearPlaneAndTheImagesSides) {
  const ViewFrame frame(obliqueCamera(), 100, 50);
  const ViewProjection view(frame);
  const auto volume = view.viewVolume(0.01f, 1.0f);
  const auto inside = [&](const Vec3& camera) {
    for (const glm::vec4& plane : volume)
      if (glm::dot(Vec3(plane), camera) + plane.w < 0.0f) return false;
    return true;
  };
  const auto atRaster = [&](float x, float y, float n) { return n * view.cameraDirection({x, y}); };
  EXPECT_TRUE(inside(atRaster(50.0f, 25.0f, 3.0f)));
  EXPECT_TRUE(inside(atRaster(-0.9f, 50.9f, 3.0f)));
  EXPECT_FALSE(inside(atRaster(-1.1f, 25.0f, 3.0f)));
  EXPECT_FALSE(inside(atRaster(50.0f, 51.1f, 3.0f)));
  EXPECT_FALSE(inside(atRaster(50.0f, 25.0f, 0.005f)));
}

TEST(ViewProjection, TurnsLinearFunctionsOfDirectionIntoAffineOnesOfRasterPosition) {
  const ViewFrame frame(obliqueCamera(), 100, 50);
  const ViewProjection view(frame);
  const glm::dvec3 form(0.3, -1.7, 2.2);
  const glm::dvec3 affine = view.rasterForm(form);
  const Vec2 raster(37.5f, 12.25f);
  const Vec3 direction = view.cameraDirection(raster);
  EXPECT_NEAR(affine.x * raster.x + affine.y * raster.y + affine.z,
              glm::dot(glm::dvec3(direction), form), 1e-6);
}

}  // namespace
}  // namespace rise
