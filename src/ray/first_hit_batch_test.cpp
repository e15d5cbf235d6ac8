#include "ray/first_hit_batch.hpp"

#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"

namespace rise {
namespace {

// A floor, a mirror, glass and an opaque sphere between a light and the
// floor, under two lights.
Scene mirrorAndGlassScene() {
  Scene scene;
  scene.image.width = 48;
  scene.image.height = 20;
  scene.camera.position = {0.0f, 1.0f, -5.0f};
  scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
  scene.camera.fovDegrees = 50.0f;
  scene.ambient = Color(0.2f);
  Material matte;
  matte.kd = 0.7f;
  matte.ks = 0.3f;
  Material mirror = matte;
  mirror.reflection = 0.5f;
  Material glass = matte;
  glass.transmission = 0.8f;
  glass.color = {0.7f, 0.9f, 1.0f};
  glass.ior = 1.5f;
  scene.materials = {matte, mirror, glass};
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 0));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(-1.0f, 0.0f, 0.5f), 0.8f, 1));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(1.0f, -0.3f, -0.5f), 0.6f, 2));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.3f, 1.5f, 0.0f), 0.4f, 0));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(1.0f, 4.0f, -2.0f), Color(0.8f)));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-4.0f, 2.0f, -1.0f), Color(0.4f)));
  return scene;
}

// Each row's first hits shaded as a batch give what shadeFirstHit gives hit
// by hit, to the bit, with the same rays; each hit's shadow rays and their
// tests are told as its own. Paths of one ray (the first hit's shadow rays
// alone) and of four.
TEST(FirstHitBatch, ShadesEachHitAsShadeFirstHitDoes) {
  const Scene scene = mirrorAndGlassScene();
  const SceneIntersector intersector(scene, Accel::Bvh, 1);
  const ViewFrame view(scene.camera, scene.image.width, scene.image.height);
  for (int maxDepth : {1, 4}) {
    const TracingContext context{scene, intersector, maxDepth};
    FirstHitBatch batch(context);
    int hitsWithoutShadowRays = 0;
    for (int y = 0; y < scene.image.height; ++y) {
      batch.clear();
      std::vector<Ray> rays;
      std::vector<Hit> hits;
      SingleRayChoices whitted;
      TraceCounters batched;
      for (int x = 0; x < scene.image.width; ++x) {
        const Ray ray = view.primaryRay(x + 0.5f, y + 0.5f);
        Hit hit;
        IntersectionCounters search;
        if (!intersector.nearest(ray, 0.0f, hit, search)) continue;
        rays.push_back(ray);
        hits.push_back(hit);
        batch.add(ray, hit, whitted, batched);
      }
      ASSERT_EQ(batch.size(), hits.size());
      batch.traceShadowRays();
      TraceCounters alone;
      for (std::size_t i = 0; i < batch.size(); ++i) {
        TraceCounters one;
        const SampleResult expected = shadeFirstHit(context, rays[i], &hits[i], whitted, one);
        const SampleResult actual = batch.finish(i, whitted, batched);
        ASSERT_EQ(actual.color, expected.color) << "row " << y << ", hit " << i;
        EXPECT_EQ(actual.depth, expected.depth);
        EXPECT_EQ(actual.normal, expected.normal);
        if (maxDepth == 1) EXPECT_EQ(batch.sentShadowRays(i), one.shadowRays > 0);
        // A hit's shadow rays' costs are its own: none where it sent none.
        EXPECT_EQ(batch.shadowRayCosts(i).tests > 0, batch.sentShadowRays(i));
        hitsWithoutShadowRays += batch.sentShadowRays(i) ? 0 : 1;
        alone += one;
      }
      EXPECT_EQ(batched.rays(), alone.rays()) << "row " << y;
      EXPECT_EQ(batched.shadowRays, alone.shadowRays) << "row " << y;
    }
    EXPECT_GT(hitsWithoutShadowRays, 0);  // the spheres' undersides face away from both lights
  }
}

}  // namespace
}  // namespace rise
