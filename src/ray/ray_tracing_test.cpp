#include "ray/ray_tracing.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "support/first_hit_testing.hpp"

namespace rise {
namespace {

constexpr Color kBackground{0.2f, 0.3f, 0.4f};

// A camera on the -z axis looking at the origin, a small image whose centre
// pixel's ray runs exactly along +z.
Scene emptyScene() {
  Scene scene;
  scene.image.width = scene.image.height = 9;
  scene.image.background = kBackground;
  scene.camera.position = {0.0f, 0.0f, -5.0f};
  scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
  scene.camera.fovDegrees = 40.0f;
  return scene;
}

int addMaterial(Scene& scene, const Material& material) {
  scene.materials.push_back(material);
  return static_cast<int>(scene.materials.size()) - 1;
}

RenderResult render(const Scene& scene, int maxDepth = 5, int threads = 1) {
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.maxDepth = maxDepth;
  settings.threads = threads;
  settings.accel = Accel::None;  // one test per shape per ray: counters easy to predict
  RenderObserver observer;
  return WhittedRayTracer().render(scene, settings, observer);
}

Color centre(const RenderResult& result) { return result.image.at(4, 4); }

void expectColorNear(const Color& actual, const Color& expected, float tolerance = 1e-4f) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TEST(WhittedRayTracer, MissesTakeTheBackground) {
  const RenderResult result = render(emptyScene());
  expectColorNear(centre(result), kBackground);
  EXPECT_TRUE(std::isinf(result.buffers.at("depth").at(4, 4).x));
}

// Head-on, N.L = 1 and R.V = 1, so the Phong model gives
// Ia ka C + Il (kd C + ks) exactly.
TEST(WhittedRayTracer, HeadOnPhongMatchesTheModel) {
  Scene scene = emptyScene();
  Material material;
  material.color = {0.8f, 0.4f, 0.2f};
  material.ka = 0.1f;
  material.kd = 0.6f;
  material.ks = 0.3f;
  material.n = 20.0f;
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, addMaterial(scene, material)));
  scene.ambient = Color(0.5f);
  const Color light{1.0f, 0.9f, 0.8f};
  scene.lights.push_back(std::make_unique<DirectionalLight>(Vec3(0.0f, 0.0f, 1.0f), light));

  const RenderResult result = render(scene);
  const Color expected = 0.5f * 0.1f * material.color + light * (0.6f * material.color + 0.3f);
  expectColorNear(centre(result), expected);
  EXPECT_NEAR(result.buffers.at("depth").at(4, 4).x, 4.0f, 1e-4f);
  expectColorNear(result.buffers.at("normal").at(4, 4), Color(0.0f, 0.0f, -1.0f));
}

// Light at 60 degrees to the normal: the diffuse term is halved.
TEST(WhittedRayTracer, DiffuseFollowsLambertsCosine) {
  Scene scene = emptyScene();
  Material matte;
  matte.ka = 0.0f;
  matte.kd = 1.0f;
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), addMaterial(scene, matte)));
  const float angle = radians(60.0f);
  scene.lights.push_back(std::make_unique<DirectionalLight>(
      Vec3(std::sin(angle), 0.0f, std::cos(angle)), Color(1.0f)));
  expectColorNear(centre(render(scene)), Color(0.5f));
}

// A sphere between the light and the floor leaves only ambient light there.
TEST(WhittedRayTracer, ShadowRaysBlockedByOpaqueShapes) {
  Scene scene = emptyScene();
  Material matte;
  matte.ka = 0.2f;
  matte.kd = 0.8f;
  const int id = addMaterial(scene, matte);
  scene.shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), id));
  scene.ambient = Color(1.0f);
  const Vec3 light{2.0f, 0.0f, -4.0f};
  scene.lights.push_back(std::make_unique<PointLight>(light, Color(1.0f)));
  const float cosine = glm::dot(Vec3(0.0f, 0.0f, -1.0f), glm::normalize(light));
  expectColorNear(centre(render(scene)), Color(0.2f + 0.8f * cosine));

  // Halfway to the light, off every camera ray.
  scene.shapes.push_back(std::make_unique<Sphere>(0.5f * light, 0.2f, id));
  expectColorNear(centre(render(scene)), Color(0.2f));
}

// A transparent sphere filters the shadow ray by t C instead of blocking it.
TEST(WhittedRayTracer, TransparentShapesFilterShadows) {
  Scene scene = emptyScene();
  Material matte;
  matte.ka = 0.0f;
  matte.kd = 1.0f;
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), addMaterial(scene, matte)));
  Material glass;
  glass.color = {1.0f, 0.5f, 1.0f};
  glass.transmission = 0.5f;
  glass.ior = 1.5f;
  scene.shapes.push_back(
      std::make_unique<Sphere>(Vec3(1.0f, 0.0f, -2.0f), 0.5f, addMaterial(scene, glass)));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(2.0f, 0.0f, -4.0f), Color(1.0f)));
  // The floor point at the origin sees the light through the glass sphere.
  const Color expected = 0.5f * glass.color *
                         glm::dot(Vec3(0.0f, 0.0f, -1.0f), glm::normalize(Vec3(2.0f, 0.0f, -4.0f)));
  expectColorNear(centre(render(scene)), expected);
}

// A mirror facing the camera shows the background behind the camera,
// weighted by its reflection coefficient.
TEST(WhittedRayTracer, MirrorReflectsWithItsWeight) {
  Scene scene = emptyScene();
  Material mirror;
  mirror.ka = 0.0f;
  mirror.kd = 0.0f;
  mirror.reflection = 0.75f;
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), addMaterial(scene, mirror)));
  expectColorNear(centre(render(scene)), 0.75f * kBackground);
}

// Along a diameter the ray crosses two interfaces without bending, and each
// one passes t C of the light.
TEST(WhittedRayTracer, RefractedRayThroughTheCentreOfAGlassSphere) {
  Scene scene = emptyScene();
  Material glass;
  glass.color = {1.0f, 0.8f, 1.0f};
  glass.ka = 0.0f;
  glass.kd = 0.0f;
  glass.transmission = 0.9f;
  glass.ior = 1.5f;
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, addMaterial(scene, glass)));
  const Color filter = 0.9f * glass.color;
  expectColorNear(centre(render(scene)), filter * filter * kBackground);
}

// Off-axis, a glass sphere bends rays: the image through it differs from the
// one through a sphere of index 1, which leaves every ray straight.
TEST(WhittedRayTracer, RefractionBendsOffAxisRays) {
  Scene scene = emptyScene();
  Material glass;
  glass.ka = glass.kd = 0.0f;
  glass.transmission = 1.0f;
  glass.ior = 1.0f;
  const int glassId = addMaterial(scene, glass);
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f), 1.5f, glassId));
  Material red;
  red.color = {1.0f, 0.0f, 0.0f};
  red.ka = 1.0f;
  red.kd = 0.0f;
  scene.ambient = Color(1.0f);
  // A small red ball behind the glass, hidden behind its centre.
  scene.shapes.push_back(
      std::make_unique<Sphere>(Vec3(0.0f, 0.0f, 4.0f), 0.3f, addMaterial(scene, red)));

  const Image straight = render(scene).image;
  scene.materials[glassId].ior = 1.5f;
  const Image bent = render(scene).image;
  EXPECT_NE(straight.at(3, 4), bent.at(3, 4));
  expectColorNear(straight.at(4, 4), bent.at(4, 4));  // the axis itself does not bend
}

// Two facing mirrors: each reflection level adds one reflection ray per pixel,
// and the depth limit stops the recursion.
TEST(WhittedRayTracer, RecursionStopsAtTheMaximumDepth) {
  Scene scene = emptyScene();
  scene.image.width = scene.image.height = 1;
  Material mirror;
  mirror.ka = mirror.kd = 0.0f;
  mirror.reflection = 1.0f;
  const int id = addMaterial(scene, mirror);
  scene.shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), id));
  scene.shapes.push_back(
      std::make_unique<Plane>(Vec3(0.0f, 0.0f, -10.0f), Vec3(0.0f, 0.0f, 1.0f), id));
  for (int depth : {1, 2, 5}) {
    const RenderResult result = render(scene, depth);
    EXPECT_EQ(result.stats.value("reflection_rays"), depth - 1) << "max depth " << depth;
  }
}

TEST(WhittedRayTracer, CountsRaysAndTests) {
  Scene scene = emptyScene();
  Material matte;
  const int id = addMaterial(scene, matte);
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, id));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f, 0.0f, 3.0f), 1.0f, id));
  const RenderResult result = render(scene);
  EXPECT_EQ(result.stats.value("primary_rays"), 81);
  EXPECT_EQ(result.stats.value("intersection_tests"), 81 * 2);
  EXPECT_EQ(result.buffers.at("cost").at(0, 0).x, 2.0f);
}

// Shade cut in two, with the shadow rays traced between the halves, gives
// shadeFirstHit's colour and buffers to the bit, and counts the same rays
// and tests: at every pixel of a scene of mirror, glass, an opaque sphere in
// a light's way, and two lights.
TEST(WhittedRayTracer, ShadesAFirstHitInTwoHalvesAsInOne) {
  const Scene scene = first_hit_testing::mirrorGlassAndBlockerScene(40, 30);
  const SceneIntersector intersector(scene, Accel::Bvh, 1);
  const ViewFrame view(scene.camera, scene.image.width, scene.image.height);
  const TracingContext context{scene, intersector, 4, view};
  int shaded = 0;
  for (int y = 0; y < scene.image.height; ++y) {
    for (int x = 0; x < scene.image.width; ++x) {
      const Ray ray = view.primaryRay(x + 0.5f, y + 0.5f);
      Hit hit;
      IntersectionCounters search;
      if (!intersector.nearest(ray, 0.0f, hit, search)) continue;
      SingleRayChoices whitted;
      TraceCounters inOne, inTwo;
      const SampleResult expected = shadeFirstHit(context, ray, &hit, whitted, inOne);
      std::vector<LitShadowRay> shadowRays;
      const FirstHitShading halves(context, ray, hit, whitted, inTwo, shadowRays);
      std::vector<Color> visible;
      for (const LitShadowRay& shadow : shadowRays)
        visible.push_back(
            intersector.transmittance(shadow.ray, 0.0f, shadow.distance, inTwo.intersections));
      const SampleResult actual = halves.finish(context, whitted, inTwo, shadowRays, visible);
      ASSERT_EQ(actual.color, expected.color) << "pixel " << x << ", " << y;
      EXPECT_EQ(actual.depth, expected.depth);
      EXPECT_EQ(actual.normal, expected.normal);
      EXPECT_EQ(inTwo.rays(), inOne.rays());
      EXPECT_EQ(inTwo.reflectionRays + inTwo.refractionRays,
                inOne.reflectionRays + inOne.refractionRays);
      EXPECT_EQ(inTwo.intersections.tests, inOne.intersections.tests);
      ++shaded;
    }
  }
  EXPECT_GT(shaded, 40 * 30 / 2);
}

}  // namespace
}  // namespace rise
