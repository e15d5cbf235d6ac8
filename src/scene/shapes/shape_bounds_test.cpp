// Every shape's bounds: a box that holds every point a ray can hit on the
// shape, checked with many random rays, and exact where the answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/transform.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;
using shape_testing::text;

std::unique_ptr<Shape> tetrahedron() {
  return std::make_unique<TriangleMesh>(
      std::vector<Vec3>{
          {0.0f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.2f}, {0.3f, 1.2f, 0.0f}, {0.4f, 0.5f, 1.1f}},
      std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, 0);
}

std::unique_ptr<Shape> placed(std::unique_ptr<Shape> shape, const TransformSpec& spec) {
  return std::make_unique<TransformedShape>(std::move(shape), worldFromObject(spec));
}

struct NamedShape {
  std::string name;
  std::unique_ptr<Shape> shape;
};

std::vector<NamedShape> boundedShapes() {
  std::vector<NamedShape> shapes;
  shapes.push_back({"sphere", std::make_unique<Sphere>(Vec3(0.3f, -0.2f, 0.1f), 1.3f, 0)});
  shapes.push_back(
      {"box", std::make_unique<Box>(Vec3(-1.0f, -0.5f, 0.0f), Vec3(1.0f, 0.5f, 1.5f), 0)});
  shapes.push_back(
      {"tilted cylinder", std::make_unique<Cylinder>(Vec3(-0.5f, -1.0f, 0.2f),
                                                     Vec3(1.0f, 2.0f, -0.5f), 0.6f, 2.0f, 0)});
  shapes.push_back({"tilted cone", std::make_unique<Cone>(Vec3(0.2f, -1.0f, -0.3f),
                                                          Vec3(-0.4f, 1.0f, 0.8f), 0.9f, 1.8f, 0)});
  shapes.push_back(
      {"triangle", std::make_unique<Triangle>(
                       std::array<Vec3, 3>{Vec3(-1.0f, -1.0f, 0.5f), Vec3(1.2f, -0.4f, -0.3f),
                                           Vec3(0.1f, 1.3f, 0.2f)},
                       0)});
  shapes.push_back(
      {"polygon", std::make_unique<ConvexPolygon>(std::vector<Vec3>{{-1.0f, -1.0f, 0.3f},
                                                                    {1.0f, -1.0f, -0.2f},
                                                                    {1.0f, 1.0f, -0.2f},
                                                                    {-1.0f, 1.0f, 0.3f}},
                                                  0)});
  shapes.push_back({"mesh", tetrahedron()});
  shapes.push_back({"rotated, scaled box", placed(std::make_unique<Box>(Vec3(-0.5f), Vec3(0.5f), 0),
                                                  {.scale = Vec3(2.0f, 1.0f, 0.5f),
                                                   .rotateDegrees = Vec3(30.0f, 45.0f, 10.0f),
                                                   .translate = Vec3(0.2f, 0.1f, -0.3f)})});
  shapes.push_back(
      {"rotated mesh", placed(tetrahedron(), {.rotateDegrees = Vec3(0.0f, 70.0f, 20.0f)})});
  return shapes;
}

// Rays from all around, aimed at random points near the origin, so that many
// of them hit each shape from every side.
std::vector<Ray> raysAroundTheOrigin(int count) {
  std::mt19937 random(1990);
  std::uniform_real_distribution<float> around(-4.0f, 4.0f);
  std::uniform_real_distribution<float> near(-1.5f, 1.5f);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec3 origin(around(random), around(random), around(random));
    const Vec3 target(near(random), near(random), near(random));
    rays.push_back(Ray{origin, target - origin});
  }
  return rays;
}

bool inside(const Vec3& point, const Bounds3& box, float tolerance) {
  return glm::all(glm::greaterThanEqual(point, box.min - Vec3(tolerance))) &&
         glm::all(glm::lessThanEqual(point, box.max + Vec3(tolerance)));
}

TEST(ShapeBounds, HoldEveryPointARayHits) {
  const std::vector<Ray> rays = raysAroundTheOrigin(4000);
  for (const auto& [name, shape] : boundedShapes()) {
    const Bounds3 box = shape->bounds();
    ASSERT_TRUE(box.isFinite()) << name;
    int hits = 0;
    for (const Ray& ray : rays) {
      const auto result = shape_testing::intersect(*shape, ray);
      if (!result.found) continue;
      ++hits;
      const Vec3 point = ray.at(result.hit.t);
      ASSERT_TRUE(inside(point, box, 1e-4f))
          << name << ": " << text(point) << " outside " << text(box.min) << " " << text(box.max);
    }
    EXPECT_GT(hits, 200) << name;
  }
}

TEST(ShapeBounds, OfEachPrimitiveHoldItsHits) {
  const std::vector<Ray> rays = raysAroundTheOrigin(4000);
  for (const auto& [name, shape] : boundedShapes()) {
    for (int primitive = 0; primitive < shape->primitiveCount(); ++primitive) {
      const Bounds3 box = shape->primitiveBounds(primitive);
      int hits = 0;
      for (const Ray& ray : rays) {
        Hit hit;
        IntersectionCounters counters;
        if (!shape->intersectPrimitive(primitive, ray, 0.0f, hit, counters)) continue;
        ++hits;
        EXPECT_EQ(hit.shape, shape.get()) << name;
        ASSERT_TRUE(inside(ray.at(hit.t), box, 1e-4f)) << name << " primitive " << primitive;
      }
      EXPECT_GT(hits, 20) << name << " primitive " << primitive;
    }
  }
}

TEST(ShapeBounds, AreTightForASphereAndABox) {
  const Bounds3 sphere = Sphere(Vec3(1.0f, 2.0f, 3.0f), 0.5f, 0).bounds();
  EXPECT_TRUE(nearlyEqual(sphere.min, {0.5f, 1.5f, 2.5f}));
  EXPECT_TRUE(nearlyEqual(sphere.max, {1.5f, 2.5f, 3.5f}));
  const Bounds3 box = Box(Vec3(1.0f, 0.0f, 2.0f), Vec3(-1.0f, 3.0f, 0.0f), 0).bounds();
  EXPECT_TRUE(nearlyEqual(box.min, {-1.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(box.max, {1.0f, 3.0f, 2.0f}));
}

TEST(ShapeBounds, OfAnUprightCylinderAreItsCapsSquare) {
  const Bounds3 box =
      Cylinder(Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 2.0f, 0.0f), 0.5f, 3.0f, 0).bounds();
  EXPECT_TRUE(nearlyEqual(box.min, {0.5f, 0.0f, -0.5f}));
  EXPECT_TRUE(nearlyEqual(box.max, {1.5f, 3.0f, 0.5f}));
}

TEST(ShapeBounds, OfATiltedCylinderHugItsCaps) {
  // The axis (1, 1, 0) / sqrt(2): each cap reaches r / sqrt(2) along x and y,
  // and r along z.
  const float s = std::sqrt(0.5f);
  const Bounds3 box = Cylinder(Vec3(0.0f), Vec3(1.0f, 1.0f, 0.0f), 1.0f, 2.0f, 0).bounds();
  const Vec3 top = 2.0f * Vec3(s, s, 0.0f);
  EXPECT_TRUE(nearlyEqual(box.min, {-s, -s, -1.0f}));
  EXPECT_TRUE(nearlyEqual(box.max, top + Vec3(s, s, 1.0f)));
}

TEST(ShapeBounds, OfAConeReachFromItsBaseToItsApex) {
  const Bounds3 box = Cone(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), 2.0f, 4.0f, 0).bounds();
  EXPECT_TRUE(nearlyEqual(box.min, {-2.0f, -2.0f, -4.0f}));
  EXPECT_TRUE(nearlyEqual(box.max, {2.0f, 2.0f, 0.0f}));
}

TEST(ShapeBounds, OfATurnedBoxHoldItsCorners) {
  // The cube [-1, 1]^3 turned 45 degrees about z reaches sqrt(2) along x and y.
  const auto turned = placed(std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f), 0),
                             {.rotateDegrees = Vec3(0.0f, 0.0f, 45.0f)});
  const float reach = std::sqrt(2.0f);
  EXPECT_TRUE(nearlyEqual(turned->bounds().min, {-reach, -reach, -1.0f}));
  EXPECT_TRUE(nearlyEqual(turned->bounds().max, {reach, reach, 1.0f}));
}

TEST(ShapeBounds, OfAPlaneAreInfinite) {
  const auto plane = placed(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0),
                            {.translate = Vec3(1.0f)});
  EXPECT_FALSE(Plane(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0).bounds().isFinite());
  EXPECT_FALSE(plane->bounds().isFinite());
}

TEST(ShapeBounds, OfAMeshAreThoseOfItsTriangles) {
  const auto mesh = tetrahedron();
  ASSERT_EQ(mesh->primitiveCount(), 4);
  EXPECT_TRUE(nearlyEqual(mesh->bounds().min, {0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(mesh->bounds().max, {1.5f, 1.2f, 1.1f}));
  // Triangle 1 joins vertices 0, 1 and 3.
  EXPECT_TRUE(nearlyEqual(mesh->primitiveBounds(1).min, {0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(mesh->primitiveBounds(1).max, {1.5f, 0.5f, 1.1f}));
}

}  // namespace
}  // namespace rise
