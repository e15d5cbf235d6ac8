#include "ray/first_hit_batch.hpp"

#include <gtest/gtest.h>

#include "support/first_hit_testing.hpp"

namespace rise {
namespace {

using first_hit_testing::mirrorGlassAndBlockerScene;

// Each row's first hits shaded as a batch give what shadeFirstHit gives hit
// by hit, to the bit, with the same rays; each hit's shadow rays and their
// tests are told as its own. Paths of one ray (the first hit's shadow rays
// alone) and of four.
TEST(FirstHitBatch, ShadesEachHitAsShadeFirstHitDoes) {
  const Scene scene = mirrorGlassAndBlockerScene(48, 20);
  const SceneIntersector intersector(scene, Accel::Bvh, 1);
  const ViewFrame view(scene.camera, scene.image.width, scene.image.height);
  for (int maxDepth : {1, 4}) {
    const TracingContext context{scene, intersector, maxDepth, view};
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
        if (maxDepth == 1) {
          EXPECT_EQ(batch.sentShadowRays(i), one.shadowRays > 0);
        }
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
