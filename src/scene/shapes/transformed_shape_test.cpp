#include "scene/shapes/transformed_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/shapes/box.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/transform.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

TransformedShape placed(std::unique_ptr<Shape> shape, const TransformSpec& spec) {
  return TransformedShape(std::move(shape), worldFromObject(spec));
}

std::unique_ptr<Shape> unitSphere() { return std::make_unique<Sphere>(Vec3(0.0f), 1.0f, 7); }

// The unit sphere made a sphere of radius 2 around (3, 0, 0).
TransformedShape bigSphere() {
  return placed(unitSphere(), {.scale = Vec3(2.0f), .translate = Vec3(3.0f, 0.0f, 0.0f)});
}

TEST(TransformedShape, KeepsTheMaterialOfTheShapeInside) { EXPECT_EQ(bigSphere().material(), 7); }

TEST(TransformedShape, HitsAScaledAndTranslatedSphere) {
  const TransformedShape sphere = bigSphere();
  const auto result = intersect(sphere, Ray{{3.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 8.0f, {3.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -1.0f}));
  EXPECT_EQ(result.hit.shape, &sphere);
}

TEST(TransformedShape, HitsAScaledSphereOffCentre) {
  // One unit off the axis the radius-2 sphere is sqrt(3) deep.
  const auto result = intersect(bigSphere(), Ray{{4.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}});
  const float depth = std::sqrt(3.0f);
  EXPECT_TRUE(hitsAt(result, 10.0f - depth, {4.0f, 0.0f, -depth}, Vec3(1.0f, 0.0f, -depth) / 2.0f));
}

TEST(TransformedShape, MissesWhereTheShapeIsNot) {
  EXPECT_TRUE(misses(intersect(bigSphere(), Ray{{0.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}})));
}

TEST(TransformedShape, ARayFromInsideExitsWithTheOutwardNormal) {
  const auto result = intersect(bigSphere(), Ray{{3.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 2.0f, {3.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}));
}

TEST(TransformedShape, TMinAndTheNearerHitMeanTheSameInBothSpaces) {
  const Ray ray{{3.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}};
  EXPECT_TRUE(hitsAt(intersect(bigSphere(), ray, /*tMin=*/9.0f), 12.0f, {3.0f, 0.0f, 2.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(misses(intersect(bigSphere(), ray, 0.0f, 7.0f), 7.0f));
}

TEST(TransformedShape, ANonUnitDirectionFindsTheSamePoint) {
  const auto result = intersect(bigSphere(), Ray{{3.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 4.0f}});
  EXPECT_TRUE(hitsAt(result, 2.0f, {3.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(TransformedShape, HitsABoxTurnedAboutY) {
  const TransformedShape box = placed(std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f), 0),
                                      {.rotateDegrees = Vec3(0.0f, 45.0f, 0.0f)});
  // Turning by +45 degrees about y takes the +x face's normal to (1, 0, -1) / sqrt(2).
  const Vec3 faceNormal = Vec3(1.0f, 0.0f, -1.0f) / std::sqrt(2.0f);
  const auto face = intersect(box, Ray{5.0f * faceNormal, -faceNormal});
  EXPECT_TRUE(hitsAt(face, 4.0f, faceNormal, faceNormal));
  // Along x the ray meets the vertical edge at x = -sqrt(2).
  const auto edge = intersect(box, Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  ASSERT_TRUE(edge.found);
  EXPECT_NEAR(edge.hit.t, 5.0f - std::sqrt(2.0f), 1e-4f);
}

TEST(TransformedShape, NonUniformScaleTurnsNormalsByTheInverseTranspose) {
  // The ellipsoid x^2 / 4 + y^2 + z^2 = 1. At (sqrt(2), sqrt(1/2), 0) its
  // normal is the gradient (x / 4, y, 0), along (1, 2, 0); scaling the sphere's
  // normal (1, 1, 0) by the scale itself would give (2, 1, 0) instead.
  const TransformedShape ellipsoid = placed(unitSphere(), {.scale = Vec3(2.0f, 1.0f, 1.0f)});
  const Vec3 point(std::sqrt(2.0f), std::sqrt(0.5f), 0.0f);
  const Vec3 normal = Vec3(1.0f, 2.0f, 0.0f) / std::sqrt(5.0f);
  const auto result = intersect(ellipsoid, Ray{point + 5.0f * normal, -normal});
  EXPECT_TRUE(hitsAt(result, 5.0f, point, normal));
}

TEST(TransformedShape, KeepsThePrimitiveOfTheShapeInside) {
  const TransformedShape quad =
      placed(std::make_unique<TriangleMesh>(
                 std::vector<Vec3>{Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(1.0f, 1.0f, 0.0f),
                                   Vec3(0.0f, 1.0f, 0.0f)},
                 std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}, 0),
             {.rotateDegrees = Vec3(-90.0f, 0.0f, 0.0f)});
  // Turned -90 degrees about x the quad lies in y = 0 with z from 0 to -1,
  // facing up.
  const auto result = intersect(quad, Ray{{0.25f, 5.0f, -0.75f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_TRUE(hitsAt(result, 5.0f, {0.25f, 0.0f, -0.75f}, {0.0f, 1.0f, 0.0f}));
  EXPECT_EQ(result.hit.primitive, 1);
}

TEST(TransformedShape, NestsInsideAnother) {
  const TransformedShape nested = placed(std::make_unique<TransformedShape>(bigSphere()),
                                         {.rotateDegrees = Vec3(0.0f, 0.0f, 90.0f)});
  // The sphere around (3, 0, 0), turned about z, lies around (0, 3, 0).
  const auto result = intersect(nested, Ray{{0.0f, 3.0f, -10.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(hitsAt(result, 8.0f, {0.0f, 3.0f, -2.0f}, {0.0f, 0.0f, -1.0f}));
  EXPECT_EQ(result.hit.shape, &nested);
}

TEST(TransformedShape, CountsOnlyTheTestsOfTheShapeInside) {
  EXPECT_EQ(intersect(bigSphere(), Ray{{3.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}}).counters.tests,
            1u);
  EXPECT_EQ(intersect(bigSphere(), Ray{{9.0f, 0.0f, -10.0f}, {0.0f, 0.0f, 1.0f}}).counters.tests,
            1u);
}

}  // namespace
}  // namespace rise
