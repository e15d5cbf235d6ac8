#include "raster/shadow_map.hpp"

#include <gtest/gtest.h>

#include "raster/visible_surface_renderer.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

// A floor, the square [-10, 10]^2 at y = 0, and over it at height 1 a
// square occluder of side 1 centred on the y axis, of material 1.
Scene squareOverAFloor() {
  Scene scene;
  scene.materials.resize(2);
  scene.shapes.push_back(std::make_unique<ConvexPolygon>(
      std::vector<Vec3>{{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}}, 0));
  scene.shapes.push_back(std::make_unique<ConvexPolygon>(
      std::vector<Vec3>{{-0.5f, 1, -0.5f}, {-0.5f, 1, 0.5f}, {0.5f, 1, 0.5f}, {0.5f, 1, -0.5f}},
      1));
  return scene;
}

TessellatedScene tessellated(const Scene& scene) {
  return tessellateForRaster(scene, RenderSettings{});
}

constexpr Vec3 kUp{0.0f, 1.0f, 0.0f};

// A point light at height 2 over the occluder's centre casts its shadow, by
// similar triangles, on the square of side 2 around the origin.
TEST(ShadowMaps, APointLightCastsTheShadowSimilarTrianglesGive) {
  Scene scene = squareOverAFloor();
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 2, 0), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  const ShadowMaps maps(scene, faces, {512, 1.5f, 1}, Workers(2));
  for (const float x : {0.0f, 0.5f, 0.9f, -0.9f})
    for (const float z : {0.0f, 0.9f, -0.9f})
      EXPECT_EQ(maps.reaching(0, Vec3(x, 0, z), kUp), Color(0.0f)) << x << " " << z;
  for (const Vec3& lit : {Vec3(1.1f, 0, 0), Vec3(0, 0, -1.1f), Vec3(3, 0, 3), Vec3(-8, 0, 2)})
    EXPECT_EQ(maps.reaching(0, lit, kUp), Color(1.0f)) << lit.x << " " << lit.z;
  // The occluder's own lit top is not shadowed by itself.
  EXPECT_EQ(maps.reaching(0, Vec3(0.2f, 1, 0.3f), kUp), Color(1.0f));
  Stats stats;
  maps.addStats(stats);
  EXPECT_EQ(stats.value("shadow_map_texels"), 6.0 * 512 * 512);
  EXPECT_GT(stats.value("shadow_tests"), stats.value("shadow_lookups"));
}

// A directional light slanting at 45 degrees in x moves the shadow of the
// occluder, one unit high, one unit along x, unchanged in size.
TEST(ShadowMaps, ADirectionalLightCastsAnOrthographicShadow) {
  Scene scene = squareOverAFloor();
  scene.lights.push_back(std::make_unique<DirectionalLight>(Vec3(1, -1, 0), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  const ShadowMaps maps(scene, faces, {512, 1.5f, 1}, Workers(2));
  EXPECT_EQ(maps.reaching(0, Vec3(1.0f, 0, 0), kUp), Color(0.0f));
  EXPECT_EQ(maps.reaching(0, Vec3(1.3f, 0, 0.3f), kUp), Color(0.0f));
  EXPECT_EQ(maps.reaching(0, Vec3(0.0f, 0, 0), kUp), Color(1.0f));
  EXPECT_EQ(maps.reaching(0, Vec3(1.0f, 0, 0.7f), kUp), Color(1.0f));
}

// A transparent occluder filters the light by its transmission times its
// colour, as a shadow ray through it does.
TEST(ShadowMaps, ATransparentOccluderFiltersTheLight) {
  Scene scene = squareOverAFloor();
  scene.materials[1].transmission = 0.5f;
  scene.materials[1].color = Color(1.0f, 0.5f, 0.25f);
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 2, 0), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  const ShadowMaps maps(scene, faces, {256, 1.5f, 1}, Workers(2));
  const Color filtered = maps.reaching(0, Vec3(0.1f, 0, 0.2f), kUp);
  EXPECT_FLOAT_EQ(filtered.r, 0.5f);
  EXPECT_FLOAT_EQ(filtered.g, 0.25f);
  EXPECT_FLOAT_EQ(filtered.b, 0.125f);
}

// Percentage-closer filtering: across the shadow's edge the light a point
// receives ramps down over a few texels instead of stepping.
TEST(ShadowMaps, FilteringRampsAcrossTheEdge) {
  Scene scene = squareOverAFloor();
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 2, 0), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  const ShadowMaps maps(scene, faces, {64, 1.5f, 2}, Workers(2));
  int between = 0;
  float last = 0.0f;
  for (float x = 0.5f; x <= 1.5f; x += 0.01f) {
    const float light = maps.reaching(0, Vec3(x, 0, 0), kUp).r;
    EXPECT_GE(light, last) << x;
    between += light > 0.0f && light < 1.0f;
    last = light;
  }
  EXPECT_GT(between, 5);
  EXPECT_EQ(last, 1.0f);
}

// Without a bias a lit surface tilted from the light shadows itself in
// places (acne); the slope-scaled bias clears it.
TEST(ShadowMaps, TheBiasClearsShadowAcne) {
  Scene scene = squareOverAFloor();
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-6, 3, 1), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  const auto selfShadowed = [&](float bias) {
    const ShadowMaps maps(scene, faces, {256, bias, 0}, Workers(2));
    int shadowed = 0;
    for (float x = 2.0f; x < 8.0f; x += 0.0137f)
      shadowed += maps.reaching(0, Vec3(x, 0, 0.31f * x), kUp) != Color(1.0f);
    return shadowed;
  };
  EXPECT_GT(selfShadowed(0.0f), 10);
  EXPECT_EQ(selfShadowed(1.5f), 0);
}

// A grid of triangles that counts how often it is asked for its bounds.
class CountedGrid final : public Shape {
 public:
  explicit CountedGrid(int side) : Shape(1), mesh_(grid(side), 1) {}

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override {
    return mesh_.intersect(ray, tMin, hit, counters);
  }
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override {
    return mesh_.surfaceAt(ray, hit);
  }
  Bounds3 bounds() const override {
    ++boundsAsked;
    return mesh_.bounds();
  }
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override {
    mesh_.tessellate(settings, out);
  }

  mutable int boundsAsked = 0;

 private:
  // side x side squares of two triangles at height 1 over [-1, 1]^2.
  static MeshGeometry grid(int side) {
    return shape_testing::squareGrid(
        side, [](Vec2 at) { return Vec3(2.0f * at.x - 1.0f, 1.0f, 2.0f * at.y - 1.0f); });
  }

  TriangleMesh mesh_;
};

// A directional light's map frames the finite shapes: each shape is asked
// for its bounds once, not once for each of its faces (a mesh finds its
// bounds over all its triangles: once a face, a large mesh took minutes).
TEST(ShadowMaps, ADirectionalLightAsksEachShapeForItsBoundsOnce) {
  Scene scene = squareOverAFloor();
  auto grid = std::make_unique<CountedGrid>(40);
  const CountedGrid& counted = *grid;
  scene.shapes.push_back(std::move(grid));
  scene.lights.push_back(std::make_unique<DirectionalLight>(Vec3(0, -1, 0), Color(1.0f)));
  const TessellatedScene faces = tessellated(scene);
  ASSERT_EQ(faces.faces.size(), 2u * 2u + 2u * 40u * 40u);
  counted.boundsAsked = 0;
  const ShadowMaps maps(scene, faces, {256, 1.5f, 1}, Workers(2));
  EXPECT_EQ(counted.boundsAsked, 1);
  EXPECT_EQ(maps.reaching(0, Vec3(0.5f, 0, 0.5f), kUp), Color(0.0f));  // under the grid
  EXPECT_EQ(maps.reaching(0, Vec3(3, 0, 3), kUp), Color(1.0f));
}

}  // namespace
}  // namespace rise
