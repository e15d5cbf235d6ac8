#include "raster/surface_shader.hpp"

#include <gtest/gtest.h>

#include <map>

#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/textures/texture.hpp"
#include "support/raster_testing.hpp"

namespace rise {
namespace {

using raster_testing::faceAt;
using raster_testing::render;

RenderResult renderShaded(const Scene& scene, Shading shading, int tessellation = 8) {
  RenderSettings settings = settingsFor(scene);
  settings.shading = shading;
  settings.tessellation = tessellation;
  return render("z-buffer", scene, settings);
}

Material shiny() {
  Material material;
  material.color = Color(0.6f, 0.3f, 0.2f);
  material.ka = 0.2f;
  material.kd = 0.5f;
  material.ks = 0.8f;
  material.n = 50.0f;
  return material;
}

// A coarse sphere (8 segments around) looked at, and lit, straight along the
// direction of the middle of one of its triangles: the highlight falls in
// the triangle's middle, 22 degrees or more from every vertex normal.
Scene coarseSphereWithAHighlightInAFace() {
  const Sphere sphere(Vec3(0.0f), 1.0f, 0);
  TessellationSettings tessellation;
  tessellation.level = 2;
  Tessellation triangles;
  sphere.tessellate(tessellation, triangles);
  const auto& [a, b, c] = triangles.triangles[20];
  const Vec3 middle = glm::normalize(triangles.vertices[a].normal + triangles.vertices[b].normal +
                                     triangles.vertices[c].normal);

  Scene scene = raster_testing::sceneSeenFrom(4.0f * middle, 101, 101);
  scene.materials[0] = shiny();
  scene.ambient = Color(0.5f);
  scene.lights.push_back(std::make_unique<DirectionalLight>(-middle, Color(1.0f)));
  scene.shapes.push_back(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, 0));
  return scene;
}

float brightest(const Image& image) {
  float largest = 0.0f;
  for (const Color& color : image.pixels()) largest = std::max(largest, color.r);
  return largest;
}

// At the highlight's centre N = L = V: I = Ia ka C + Il (kd C + ks). Phong
// shading finds it there; Gouraud, evaluating the model only at vertices
// where (R.V)^50 is nearly 0, smears it away.
TEST(SurfaceShader, PhongKeepsTheHighlightGouraudMisses) {
  const Scene scene = coarseSphereWithAHighlightInAFace();
  const Material material = shiny();
  const float peak =
      0.5f * material.ka * material.color.r + material.kd * material.color.r + material.ks;
  const float phong = brightest(renderShaded(scene, Shading::Phong, 2).image);
  const float gouraud = brightest(renderShaded(scene, Shading::Gouraud, 2).image);
  EXPECT_NEAR(phong, peak, 0.03f * peak);
  EXPECT_LT(gouraud, peak - 0.7f * material.ks);
}

TEST(SurfaceShader, FlatGivesAFaceOneColour) {
  const Scene scene = coarseSphereWithAHighlightInAFace();
  const RenderResult flat = renderShaded(scene, Shading::Flat, 2);
  std::map<int, Color> colorOfFace;
  int faces = 0;
  for (int y = 0; y < flat.image.height(); ++y) {
    for (int x = 0; x < flat.image.width(); ++x) {
      const int face = faceAt(flat, x, y);
      if (face < 0) continue;
      const auto [known, added] = colorOfFace.try_emplace(face, flat.image.at(x, y));
      faces += added;
      EXPECT_EQ(known->second, flat.image.at(x, y)) << "face " << face;
    }
  }
  EXPECT_GT(faces, 10);
}

// A flat polygon, lit by a point light: per-pixel Phong shading is the ray
// tracer's own model at each pixel (nothing casts a shadow here).
TEST(SurfaceShader, PhongOnAPolygonIsTheRayTracersModel) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0.5f, 1.0f, -4.0f), 48, 36);
  scene.materials[0] = shiny();
  scene.materials[0].n = 5.0f;
  scene.ambient = Color(0.2f);
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(-1.0f, 2.0f, -2.0f), Color(0.9f)));
  scene.shapes.push_back(
      std::make_unique<ConvexPolygon>(std::vector{Vec3(-2.0f, -1.5f, 0.5f), Vec3(2.0f, -1.5f, 0.0f),
                                                  Vec3(2.0f, 1.5f, 0.0f), Vec3(-2.0f, 1.5f, 0.5f)},
                                      0));
  const RenderResult raster = renderShaded(scene, Shading::Phong);
  const RenderResult traced = render("ray-tracing", scene);
  int compared = 0;
  for (int y = 0; y < 36; ++y) {
    for (int x = 0; x < 48; ++x) {
      if (faceAt(raster, x, y) < 0) continue;
      ++compared;
      const Color difference = raster.image.at(x, y) - traced.image.at(x, y);
      EXPECT_LT(glm::length(difference), 1e-4f) << x << ", " << y;
    }
  }
  EXPECT_GT(compared, 500);
}

// The texture's colour is looked up at every pixel whatever the shading: the
// squares of a checkerboard show within single faces of the floor.
TEST(SurfaceShader, TexturesEveryPixelInEveryShading) {
  Scene scene = raster_testing::sceneSeenFrom(Vec3(0.0f, 2.0f, -3.0f), 40, 40);
  scene.materials[0].texture = std::make_shared<CheckerTexture>(Color(1.0f), Color(0.0f), 0.25f);
  scene.shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0));
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
    const RenderResult result = renderShaded(scene, shading);
    std::map<int, std::pair<float, float>> darkestAndLightest;
    for (int y = 0; y < 40; ++y) {
      for (int x = 0; x < 40; ++x) {
        const int face = faceAt(result, x, y);
        if (face < 0) continue;
        auto [range, added] = darkestAndLightest.try_emplace(face, kInfinity, 0.0f);
        range->second.first = std::min(range->second.first, result.image.at(x, y).r);
        range->second.second = std::max(range->second.second, result.image.at(x, y).r);
      }
    }
    int checkeredFaces = 0;
    for (const auto& [face, range] : darkestAndLightest)
      checkeredFaces += range.first < 1e-6f && range.second > 1.0f - 1e-6f;
    EXPECT_GT(checkeredFaces, 0);
  }
}

}  // namespace
}  // namespace rise
