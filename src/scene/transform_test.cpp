#include "scene/transform.hpp"

#include <gtest/gtest.h>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::nearlyEqual;

Vec3 movePoint(const TransformSpec& spec, const Vec3& p) {
  return Vec3(worldFromObject(spec) * glm::vec4(p, 1.0f));
}

Vec3 moveDirection(const TransformSpec& spec, const Vec3& d) {
  return Vec3(worldFromObject(spec) * glm::vec4(d, 0.0f));
}

TEST(WorldFromObject, TheDefaultSpecIsTheIdentity) {
  EXPECT_EQ(worldFromObject(TransformSpec{}), Mat4(1.0f));
}

TEST(WorldFromObject, ScalesBeforeTranslating) {
  const TransformSpec spec{.scale = Vec3(2.0f), .translate = Vec3(1.0f, 0.0f, 0.0f)};
  EXPECT_TRUE(nearlyEqual(movePoint(spec, {1.0f, 0.0f, 0.0f}), {3.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(moveDirection(spec, {1.0f, 0.0f, 0.0f}), {2.0f, 0.0f, 0.0f}));
}

TEST(WorldFromObject, RotatesCounterClockwiseAboutEachAxis) {
  EXPECT_TRUE(nearlyEqual(movePoint({.rotateDegrees = {90.0f, 0.0f, 0.0f}}, {0.0f, 1.0f, 0.0f}),
                          {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearlyEqual(movePoint({.rotateDegrees = {0.0f, 90.0f, 0.0f}}, {0.0f, 0.0f, 1.0f}),
                          {1.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(movePoint({.rotateDegrees = {0.0f, 0.0f, 90.0f}}, {1.0f, 0.0f, 0.0f}),
                          {0.0f, 1.0f, 0.0f}));
}

TEST(WorldFromObject, RotatesAboutXThenYThenZ) {
  // The other order would leave these points elsewhere: y then x takes
  // (0, 1, 0) to (0, 0, 1), and z then y takes (0, 0, 1) to (1, 0, 0).
  EXPECT_TRUE(nearlyEqual(movePoint({.rotateDegrees = {90.0f, 90.0f, 0.0f}}, {0.0f, 1.0f, 0.0f}),
                          {1.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(nearlyEqual(movePoint({.rotateDegrees = {0.0f, 90.0f, 90.0f}}, {0.0f, 0.0f, 1.0f}),
                          {0.0f, 1.0f, 0.0f}));
}

TEST(WorldFromObject, ScalesThenRotatesThenTranslates) {
  const TransformSpec spec{.scale = {2.0f, 1.0f, 1.0f},
                           .rotateDegrees = {0.0f, 0.0f, 90.0f},
                           .translate = {0.0f, 0.0f, 5.0f}};
  EXPECT_TRUE(nearlyEqual(movePoint(spec, {1.0f, 0.0f, 0.0f}), {0.0f, 2.0f, 5.0f}));
}

}  // namespace
}  // namespace rise
