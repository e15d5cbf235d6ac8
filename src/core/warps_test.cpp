#include "core/warps.hpp"

#include <gtest/gtest.h>

#include "support/chi_square_testing.hpp"

namespace rise {
namespace {

using namespace chi_square_testing;

// The chi-square tests of this file, each held to its share of 0.01.
constexpr int kTests = 9;
const double kSignificance = significanceFor(kTests);

TEST(SquareToDisk, MapsIntoTheDiskAndTheCentreToTheCentre) {
  EXPECT_EQ(squareToDisk(Vec2(0.5f)), Vec2(0.0f));
  EXPECT_NEAR(glm::length(squareToDisk(Vec2(1.0f, 0.5f))), 1.0f, 1e-6f);
}

TEST(Warps, TheDiskIsUniform) {
  const ChiSquareOutcome outcome =
      chiSquareOfDiskPoints(squareToDisk, [](const Vec2&) { return kDiskDensity; });
  EXPECT_TRUE(outcome.passes(kSignificance)) << outcome.report;
}

TEST(Warps, TheSphereIsUniform) {
  const ChiSquareOutcome outcome = chiSquareOfDirections(
      squareToUniformSphere, [](const Vec3&) { return kUniformSphereDensity; });
  EXPECT_TRUE(outcome.passes(kSignificance)) << outcome.report;
}

TEST(Warps, TheHemisphereIsUniform) {
  const ChiSquareOutcome outcome = chiSquareOfDirections(
      squareToUniformHemisphere,
      [](const Vec3& direction) { return direction.z >= 0.0f ? kUniformHemisphereDensity : 0.0f; });
  EXPECT_TRUE(outcome.passes(kSignificance)) << outcome.report;
}

TEST(Warps, TheCosineHemisphereFollowsTheCosine) {
  const ChiSquareOutcome outcome =
      chiSquareOfDirections(squareToCosineHemisphere, cosineHemisphereDensity);
  EXPECT_TRUE(outcome.passes(kSignificance)) << outcome.report;
}

// A wide cone and a narrow one, whose cap is a few of the grid's cells.
TEST(Warps, TheConeIsUniformWithinItsAngle) {
  for (const float cosine : {0.5f, 0.95f}) {
    const ChiSquareOutcome outcome = chiSquareOfDirections(
        [&](const Vec2& u) { return squareToUniformCone(u, cosine); },
        [&](const Vec3& direction) { return uniformConeDensity(direction, cosine); });
    EXPECT_TRUE(outcome.passes(kSignificance)) << "cosine " << cosine << ": " << outcome.report;
  }
}

// A wide lobe, a diffuse one (n = 0) and a sharp one.
TEST(Warps, ThePhongLobeFollowsTheCosinePower) {
  for (const float exponent : {0.0f, 4.0f, 60.0f}) {
    const ChiSquareOutcome outcome = chiSquareOfDirections(
        [&](const Vec2& u) { return squareToPhongLobe(u, exponent); },
        [&](const Vec3& direction) { return phongLobeDensity(direction, exponent); });
    EXPECT_TRUE(outcome.passes(kSignificance)) << "n " << exponent << ": " << outcome.report;
  }
}

// The test can fail: samples of one distribution held against another's
// density are rejected, whether they only lean the wrong way or fall where
// the density says none can.
TEST(Warps, AWrongDensityIsRejected) {
  const ChiSquareOutcome leaning =
      chiSquareOfDirections(squareToUniformHemisphere, cosineHemisphereDensity);
  EXPECT_LT(leaning.pValue, 1e-6) << leaning.report;
  const ChiSquareOutcome slightly = chiSquareOfDirections(
      [](const Vec2& u) { return squareToUniformCone(u, 0.5f); },
      [](const Vec3& direction) { return uniformConeDensity(direction, 0.45f); });
  EXPECT_FALSE(slightly.passes(kSignificance)) << slightly.report;
  const ChiSquareOutcome outside = chiSquareOfDirections(
      squareToUniformSphere,
      [](const Vec3& direction) { return direction.z >= 0.0f ? kUniformHemisphereDensity : 0.0f; });
  EXPECT_GT(outside.outside, 0);
  EXPECT_FALSE(outside.passes(kSignificance));
}

TEST(Warps, FromLocalTurnsTheAxisOntoItself) {
  const Vec3 axis = glm::normalize(Vec3(1.0f, -2.0f, 0.5f));
  EXPECT_NEAR(glm::distance(fromLocal(Vec3(0.0f, 0.0f, 1.0f), axis), axis), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(fromLocal(Vec3(1.0f, 0.0f, 0.0f), axis), axis), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(fromLocal(glm::normalize(Vec3(0.3f, 0.4f, 0.5f)), axis)), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace rise
