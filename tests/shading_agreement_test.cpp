// The two families shade alike where rays add nothing: one light, no shadow
// falling on a visible surface, no mirror, no glass. There the visible-surface
// algorithms, whose polygons carry the exact surface's normals at their
// corners, must match the ray tracer at every pixel but the outlines: within a
// few levels with Phong shading (a normal per pixel), within a looser bound
// with Gouraud's (a colour per vertex), and a facet of the tessellation must
// not show in either.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/image_agreement_testing.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using namespace image_agreement_testing;

constexpr std::array<std::string_view, 4> kVisibleSurfaceAlgorithms = {
    "depth-sort", "area-subdivision", "z-buffer", "scanline"};

// An ellipsoid as a smooth mesh: its exact normals at the vertices of a
// latitude-longitude grid, which the ray tracer and the polygons interpolate
// alike.
std::unique_ptr<Shape> smoothEllipsoid(const Vec3& radii, int material) {
  constexpr int kRings = 12, kSegments = 24;
  MeshGeometry mesh;
  for (int ring = 0; ring <= kRings; ++ring) {
    const float polar = kPi * static_cast<float>(ring) / kRings;
    for (int segment = 0; segment < kSegments; ++segment) {
      const float turn = 2.0f * kPi * static_cast<float>(segment) / kSegments;
      const Vec3 unit(std::sin(polar) * std::cos(turn), std::cos(polar),
                      std::sin(polar) * std::sin(turn));
      mesh.positions.push_back(radii * unit);
      mesh.normals.push_back(glm::normalize(unit / radii));
    }
  }
  const auto at = [](int ring, int segment) { return ring * kSegments + segment % kSegments; };
  for (int ring = 0; ring < kRings; ++ring)
    for (int segment = 0; segment < kSegments; ++segment) {
      const int a = at(ring, segment), b = at(ring, segment + 1);
      const int c = at(ring + 1, segment), d = at(ring + 1, segment + 1);
      if (ring > 0) mesh.triangles.push_back({a, b, c});
      if (ring + 1 < kRings) mesh.triangles.push_back({b, d, c});
    }
  return std::make_unique<TriangleMesh>(std::move(mesh), material);
}

struct ShapeCase {
  std::string name;
  std::function<std::unique_ptr<Shape>()> make;
};

std::vector<ShapeCase> shapeCases() {
  return {
      {"sphere", [] { return std::make_unique<Sphere>(Vec3(0.0f, 0.8f, 0.0f), 1.0f, 0); }},
      {"cylinder",
       [] {
         return std::make_unique<Cylinder>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0.8f, 1.5f, 0);
       }},
      {"cone",
       [] { return std::make_unique<Cone>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 1.0f, 1.6f, 0); }},
      {"tilted cone",
       [] {
         return std::make_unique<Cone>(Vec3(0.0f, 0.4f, 0.0f), Vec3(0.3f, 1.0f, -0.6f), 0.9f, 1.2f,
                                       0);
       }},
      {"box",
       [] { return std::make_unique<Box>(Vec3(-0.8f, 0.0f, -0.6f), Vec3(0.7f, 1.2f, 0.9f), 0); }},
      {"polygon",
       [] {
         return std::make_unique<ConvexPolygon>(std::vector<Vec3>{{-1.2f, 0.0f, 0.5f},
                                                                  {1.0f, 0.0f, 0.8f},
                                                                  {1.3f, 1.6f, 0.2f},
                                                                  {-0.2f, 2.0f, -0.1f},
                                                                  {-1.4f, 1.2f, 0.1f}},
                                                0);
       }},
      {"mesh", [] { return smoothEllipsoid(Vec3(1.1f, 0.8f, 0.9f), 0); }},
  };
}

// One grey shape seen from above and in front, lit by one point light
// beside the eye: no other surface for a shadow to fall on.
Scene sceneOf(const ShapeCase& shape, const Material& material, int width, int height,
              const Vec3& light = Vec3(3.0f, 4.5f, -5.0f)) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.image.background = Color(0.1f, 0.2f, 0.3f);
  scene.camera.position = Vec3(1.5f, 2.8f, -4.0f);
  scene.camera.lookAt = Vec3(0.0f, 0.7f, 0.0f);
  scene.camera.fovDegrees = 45.0f;
  scene.ambient = Color(0.4f);
  scene.lights.push_back(std::make_unique<PointLight>(light, Color(1.0f)));
  scene.materials.push_back(material);
  scene.shapes.push_back(shape.make());
  return scene;
}

// Light grey, with a highlight when ks > 0; ambient and diffuse as the
// model's defaults.
Material grey(float ks) {
  Material material;
  material.color = Color(0.8f);
  material.ks = ks;
  material.n = 12.0f;
  return material;
}

RenderSettings settingsFor(const Scene& scene, Shading shading, int tessellation) {
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.threads = 2;
  settings.shading = shading;
  settings.tessellation = tessellation;
  return settings;
}

// The visible-surface algorithms against the ray tracer on every shape at
// the given tessellations, in a square image and in a wide one: no pixel
// inside the outlines more than `allowedLevels` apart, and no step from a
// pixel to the next more than `allowedStep` apart (an edge that one image
// has and the other has not).
void expectAgreement(const Material& material, Shading shading, std::span<const int> levels,
                     int allowedLevels, int allowedStep) {
  for (const ShapeCase& shape : shapeCases())
    for (const auto& [width, height] : {std::pair{150, 150}, std::pair{240, 120}})
      for (int tessellation : levels) {
        const Scene scene = sceneOf(shape, material, width, height);
        const RenderSettings settings = settingsFor(scene, shading, tessellation);
        const RenderResult traced = renderWith("ray-tracing", scene, settings);
        for (std::string_view algorithm : kVisibleSurfaceAlgorithms) {
          const RenderResult drawn = renderWith(algorithm, scene, settings);
          const std::string what = std::string(algorithm) + " on the " + shape.name +
                                   " at tessellation " + std::to_string(tessellation) + ", " +
                                   std::to_string(width) + " x " + std::to_string(height);
          const Agreement colours = agreementInside(scene, drawn, traced);
          EXPECT_GT(colours.pixelsCompared, width * height / 20) << what;
          EXPECT_LE(colours.worst, allowedLevels) << what << ": " << colours;
          const Agreement steps = stepAgreementInside(scene, drawn, traced);
          EXPECT_LE(steps.worst, allowedStep) << what << ", steps: " << steps;
        }
      }
}

// At the default tessellation (8) a sphere's facets lie far enough inside it
// to move its shading by up to 5 levels where the light grazes it; a finer
// one, less. A facet shows as a step of 10 levels and more: the cone's did
// when its apex took one normal a facet.
TEST(ShadingAgreement, PhongShadingMatchesTheRayTracerOnEveryShape) {
  constexpr int kLevels[] = {8, 12, 24};
  expectAgreement(grey(0.3f), Shading::Phong, kLevels, 5, 3);
}

// Colours interpolated from the vertices drift further from the ray
// tracer's, but do not step either.
TEST(ShadingAgreement, GouraudShadingMatchesTheRayTracerLooselyOnEveryShape) {
  constexpr int kLevels[] = {8, 12, 24};
  expectAgreement(grey(0.0f), Shading::Gouraud, kLevels, 8, 3);
}

// Lit from the other side, the smooth mesh turns from the light across the
// image: the line where the light grazes it, the terminator, runs over its
// front. The polygons of the visible-surface algorithms are the mesh's own
// triangles, so that the two families must agree there too. The ray
// tracer, which took the flat triangles' side of the light and sent its
// shadow rays from them, cut the light off along their edges in steps of 33
// to 53 levels; it takes both from the smooth surface
// (ray/shadow_terminator.hpp).
TEST(ShadingAgreement, TheRayTracersTerminatorFollowsASmoothMeshsNormals) {
  const ShapeCase mesh{"mesh", [] { return smoothEllipsoid(Vec3(1.1f, 0.8f, 0.9f), 0); }};
  for (const Vec3 light :
       {Vec3(-3.0f, 5.0f, -4.0f), Vec3(-4.0f, 1.0f, 0.0f), Vec3(0.0f, 4.0f, 3.0f)})
    for (const auto& [width, height] : {std::pair{150, 150}, std::pair{240, 120}}) {
      const Scene scene = sceneOf(mesh, grey(0.3f), width, height, light);
      const RenderSettings settings = settingsFor(scene, Shading::Phong, kDefaultTessellationLevel);
      const RenderResult drawn = renderWith("z-buffer", scene, settings);
      const RenderResult traced = renderWith("ray-tracing", scene, settings);
      const Agreement colours = agreementInside(scene, drawn, traced);
      EXPECT_LE(colours.worst, 3) << shape_testing::text(light) << ": " << colours;
      const Agreement steps = stepAgreementInside(scene, drawn, traced);
      EXPECT_LE(steps.worst, 3) << shape_testing::text(light) << ", steps: " << steps;
    }
}

}  // namespace
}  // namespace rise
