// Both of radiosity's ways to a form factor, the closed form with its
// subdivision (form_factors.hpp) and the hemicube (hemicube.hpp), held to
// the closed forms of three configurations, each within 1% at the test's
// resolution and closer as it grows.
#include "radiosity/form_factors.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "radiosity/hemicube.hpp"
#include "render/render_settings.hpp"

namespace rise {
namespace {

using Triangles = std::vector<std::array<Vec3, 3>>;

// The form factor from a point to the triangles, by `method`, at
// `resolution` (the hemicube's side; the closed form's depth of
// subdivision).
double pointToTriangles(const Vec3& point, const Vec3& normal, const Triangles& triangles,
                        const Vec3& trianglesNormal, FormFactorMethod method, int resolution) {
  if (method == FormFactorMethod::Rays) {
    double sum = 0.0;
    for (const std::array<Vec3, 3>& triangle : triangles)
      sum += formFactorToTriangle(point, normal, triangle, trianglesNormal, resolution);
    return sum;
  }
  std::vector<HemicubeTriangle> receiving;
  for (const std::array<Vec3, 3>& triangle : triangles) receiving.push_back({triangle, 0});
  Hemicube hemicube(resolution);
  std::array<float, 1> formFactor{};
  hemicube.addFormFactors(point, normal, receiving, -1, formFactor);
  return formFactor[0];
}

// The form factor from the unit square at z = 0 (normal +z) to the
// triangles: the mean over m x m points of the square.
double squareToTriangles(const Triangles& triangles, const Vec3& trianglesNormal,
                         FormFactorMethod method, int resolution) {
  constexpr int m = 16;
  double sum = 0.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      sum += pointToTriangles({(i + 0.5f) / m, (j + 0.5f) / m, 0.0f}, {0.0f, 0.0f, 1.0f}, triangles,
                              trianglesNormal, method, resolution);
  return sum / (m * m);
}

Triangles quadrilateral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return {{a, b, c}, {a, c, d}};
}

// The relative errors of a method at a coarse and at the test's resolution.
struct Errors {
  double coarse, fine;
};

template <typename FormFactorAt>
Errors errorsOf(FormFactorMethod method, double exact, FormFactorAt&& at) {
  const int coarse = method == FormFactorMethod::Rays ? 1 : 16;
  const int fine = method == FormFactorMethod::Rays ? 8 : 256;
  return {std::abs(at(coarse) - exact) / exact, std::abs(at(fine) - exact) / exact};
}

void expectWithinOnePercentAndConverging(const Errors& errors, FormFactorMethod method) {
  EXPECT_LT(errors.fine, 0.01) << formFactorMethodName(method);
  EXPECT_LE(errors.fine, errors.coarse) << formFactorMethodName(method);
}

// Hottel's crossed-strings result for two rectangles meeting at a right
// angle along a common edge of length l, the first w wide and the second h
// tall: the form factor from the first to the second (Howell's catalogue,
// configuration C-14).
double perpendicularRectangles(double l, double w, double h) {
  const double W = w / l, H = h / l, W2 = W * W, H2 = H * H, D = std::sqrt(W2 + H2);
  const double logarithm = std::log((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                           W2 * std::log(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                           H2 * std::log(H2 * (1 + W2 + H2) / ((1 + H2) * (W2 + H2)));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - D * std::atan(1 / D) + logarithm / 4) /
         (kPi * W);
}

TEST(FormFactors, TwoParallelSquaresOneApartShare0_1998) {
  const Triangles facing = quadrilateral({0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  for (const FormFactorMethod method : kAllFormFactorMethods)
    expectWithinOnePercentAndConverging(
        errorsOf(method, 0.19982,
                 [&](int resolution) {
                   return squareToTriangles(facing, {0, 0, -1}, method, resolution);
                 }),
        method);
}

TEST(FormFactors, PerpendicularRectanglesFollowHottelsFormula) {
  EXPECT_NEAR(perpendicularRectangles(1, 1, 1), 0.20004, 1e-5);
  // The unit square at z = 0 and a wall two tall along its edge x = 0.
  const Triangles wall = quadrilateral({0, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 2});
  const double exact = perpendicularRectangles(1, 1, 2);
  for (const FormFactorMethod method : kAllFormFactorMethods)
    expectWithinOnePercentAndConverging(
        errorsOf(method, exact,
                 [&](int resolution) {
                   return squareToTriangles(wall, {1, 0, 0}, method, resolution);
                 }),
        method);
}

TEST(FormFactors, FromAPointToADiscOnItsAxis) {
  // A disc of radius 1, 2 above the point, meshed as a model would be: 16
  // rings of 128 sectors, each cell two triangles (the centre's one). Its
  // closed form, R^2 / (R^2 + h^2), for the polygon's area.
  constexpr int kSides = 128, kRings = 16;
  Triangles disc;
  const auto at = [&](int ring, int sector) {
    const float r = static_cast<float>(ring) / kRings, a = 2.0f * kPi * sector / kSides;
    return Vec3(r * std::cos(a), r * std::sin(a), 2.0f);
  };
  for (int ring = 0; ring < kRings; ++ring)
    for (int k = 0; k < kSides; ++k) {
      disc.push_back({at(ring, k), at(ring + 1, k), at(ring + 1, k + 1)});
      if (ring > 0) disc.push_back({at(ring, k), at(ring + 1, k + 1), at(ring, k + 1)});
    }
  const double area = 0.5 * kSides * std::sin(2.0 * kPi / kSides);
  const double exact = (area / kPi) / (area / kPi + 4.0);
  for (const FormFactorMethod method : kAllFormFactorMethods)
    expectWithinOnePercentAndConverging(errorsOf(method, exact,
                                                 [&](int resolution) {
                                                   // A point off the centre, so that no texel edge
                                                   // lines up with the disc's.
                                                   return pointToTriangles(
                                                       {0.013f, 0.007f, 0.0f}, {0, 0, 1}, disc,
                                                       {0, 0, -1}, method, resolution);
                                                 }),
                                        method);
}

TEST(Hemicube, DeltaFormFactorsSumToOne) {
  for (const int resolution : {8, 64, 256}) {
    const Hemicube hemicube(resolution);
    double sum = 0.0;
    for (int face = 0; face < 5; ++face) {
      const PixelRect rows = hemicube.above(face);
      for (int y = rows.y0; y < rows.y1; ++y)
        for (int x = rows.x0; x < rows.x1; ++x) sum += hemicube.deltaFormFactor(face, x, y);
    }
    EXPECT_NEAR(sum, 1.0, 2.0 / resolution) << resolution;
  }
}

TEST(Hemicube, ANearerSurfaceHidesAFartherOne) {
  // A small square 1 above the point hides part of a large one 2 above.
  const Triangles near =
      quadrilateral({-0.25f, -0.25f, 1}, {0.25f, -0.25f, 1}, {0.25f, 0.25f, 1}, {-0.25f, 0.25f, 1});
  const Triangles far = quadrilateral({-4, -4, 2}, {4, -4, 2}, {4, 4, 2}, {-4, 4, 2});
  std::vector<HemicubeTriangle> both;
  for (const auto& triangle : near) both.push_back({triangle, 0});
  for (const auto& triangle : far) both.push_back({triangle, 1});
  Hemicube hemicube(128);
  std::array<float, 2> formFactors{};
  hemicube.addFormFactors({0.01f, 0.02f, 0.0f}, {0, 0, 1}, both, -1, formFactors);
  const double nearAlone = pointToTriangles({0.01f, 0.02f, 0.0f}, {0, 0, 1}, near, {0, 0, -1},
                                            FormFactorMethod::Rays, 8);
  const double farAlone =
      pointToTriangles({0.01f, 0.02f, 0.0f}, {0, 0, 1}, far, {0, 0, -1}, FormFactorMethod::Rays, 8);
  EXPECT_NEAR(formFactors[0], nearAlone, 0.02 * nearAlone);
  EXPECT_NEAR(formFactors[1], farAlone - nearAlone, 0.02 * (farAlone - nearAlone));
}

}  // namespace
}  // namespace rise
