// Pearson's chi-square test of a sampling routine against the density it
// claims, as pbrt-v4, Mitsuba 3 and Nori test their warps and BSDFs: about
// a million independent samples are counted in the cells of a grid over the
// domain, each cell's expected count is the density integrated over it
// (Simpson's rule on a finer grid) times the samples, cells expected fewer
// than five samples are pooled until they are not, and the statistic's tail
// probability under the chi-square distribution is the p-value. The
// hypothesis that the samples follow the density is rejected when the
// p-value falls below the significance level, 0.01 for all the tests of a
// suite together (Sidak's correction: 1 - 0.99^(1 / tests) for each).
//
// Every domain is seen through coordinates (a, b) of the unit square, in
// which the grid's cells are equal: directions by (cos(theta) + 1) / 2 and
// phi / (2 pi), cells of equal solid angle; points of the unit disk by r^2
// and their angle / (2 pi), cells of equal area. A sample outside the domain
// (a direction not of unit length, a point beyond the disk) fails the test.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/math.hpp"
#include "core/random.hpp"

namespace rise::chi_square_testing {

// The regularized upper incomplete gamma function Q(s, x) =
// Gamma(s, x) / Gamma(s): by its power series below x = s + 1, by its
// continued fraction (evaluated by Lentz's method) above.
inline double upperIncompleteGamma(double s, double x) {
  if (x <= 0.0) return 1.0;
  const double logPrefactor = s * std::log(x) - x - std::lgamma(s);
  if (x < s + 1.0) {
    double term = 1.0 / s, sum = term;
    for (int n = 1; n < 10000 && std::abs(term) > 1e-16 * std::abs(sum); ++n) {
      term *= x / (s + n);
      sum += term;
    }
    return 1.0 - std::exp(logPrefactor) * sum;
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - s, c = 1.0 / kTiny, d = 1.0 / b, fraction = d;
  for (int n = 1; n < 10000; ++n) {
    const double a = -n * (n - s);
    b += 2.0;
    d = a * d + b;
    d = std::abs(d) < kTiny ? kTiny : d;
    c = b + a / c;
    c = std::abs(c) < kTiny ? kTiny : c;
    d = 1.0 / d;
    const double step = d * c;
    fraction *= step;
    if (std::abs(step - 1.0) < 1e-16) break;
  }
  return std::exp(logPrefactor) * fraction;
}

// The probability that a chi-square variable of `freedom` degrees exceeds
// `statistic`.
inline double chiSquareTail(double statistic, int freedom) {
  return upperIncompleteGamma(0.5 * freedom, 0.5 * statistic);
}

// The significance each of `tests` tests is held to, so that all together
// wrongly reject a right density with probability 0.01.
inline double significanceFor(int tests) {
  return 1.0 - std::pow(1.0 - 0.01, 1.0 / static_cast<double>(tests));
}

struct ChiSquareOutcome {
  double statistic = 0.0;
  int freedom = 0;
  double pValue = 0.0;
  int outside = 0;     // samples outside the domain, or where the density is 0
  std::string report;  // what a failing test prints

  bool passes(double significance) const { return outside == 0 && pValue >= significance; }
};

struct Grid {
  int cellsA = 40;
  int cellsB = 80;
  int samples = 1'000'000;
  std::uint64_t seed = 1;
};

// The test over the unit square: `draw` gives a sample's coordinates (none
// where it fell outside the domain); `density(a, b)` the density per unit
// of the square's area.
inline ChiSquareOutcome chiSquareOnSquare(const std::function<std::optional<Vec2>(Rng&)>& draw,
                                          const std::function<double(double, double)>& density,
                                          const Grid& grid = {}) {
  const auto cells = static_cast<std::size_t>(grid.cellsA) * grid.cellsB;
  std::vector<double> observed(cells, 0.0), expected(cells, 0.0);
  ChiSquareOutcome outcome;
  Rng rng(grid.seed);
  for (int i = 0; i < grid.samples; ++i) {
    const std::optional<Vec2> at = draw(rng);
    if (!at || at->x < 0.0f || at->x > 1.0f || at->y < 0.0f || at->y > 1.0f) {
      ++outcome.outside;
      continue;
    }
    const int a = std::min(grid.cellsA - 1, static_cast<int>(at->x * grid.cellsA));
    const int b = std::min(grid.cellsB - 1, static_cast<int>(at->y * grid.cellsB));
    observed[static_cast<std::size_t>(b) * grid.cellsA + a] += 1.0;
  }
  // Simpson's rule on 16 x 16 intervals of each cell, its edges taken a
  // hair inside, so that a density that jumps on a cell's edge (a
  // hemisphere's horizon, a cone's rim) is integrated on each side as its own.
  constexpr int kSteps = 16;
  constexpr double kInside = 1e-4;
  const auto at = [&](int cell, int step) {
    return std::clamp(static_cast<double>(step) / kSteps, kInside, 1.0 - kInside) + cell;
  };
  const double da = 1.0 / grid.cellsA, db = 1.0 / grid.cellsB;
  const auto weight = [](int step) {
    return step == 0 || step == kSteps ? 1.0 : 2.0 + 2.0 * (step % 2);
  };
  for (int b = 0; b < grid.cellsB; ++b)
    for (int a = 0; a < grid.cellsA; ++a) {
      double sum = 0.0;
      for (int j = 0; j <= kSteps; ++j)
        for (int i = 0; i <= kSteps; ++i)
          sum += weight(i) * weight(j) * density(at(a, i) * da, at(b, j) * db);
      expected[static_cast<std::size_t>(b) * grid.cellsA + a] =
          sum * da * db / (9.0 * kSteps * kSteps) * grid.samples;
    }
  for (std::size_t cell = 0; cell < cells; ++cell)
    if (expected[cell] == 0.0 && observed[cell] > 0.0)
      outcome.outside += static_cast<int>(observed[cell]);

  // Pool the cells expected fewest samples until each pool expects five.
  std::vector<std::size_t> order(cells);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return expected[x] < expected[y]; });
  double pooledObserved = 0.0, pooledExpected = 0.0;
  int kept = 0;
  const auto add = [&](double seen, double wanted) {
    outcome.statistic += (seen - wanted) * (seen - wanted) / wanted;
    ++kept;
  };
  for (const std::size_t cell : order) {
    if (expected[cell] == 0.0) continue;
    if (expected[cell] < 5.0 || pooledExpected > 0.0) {
      pooledObserved += observed[cell];
      pooledExpected += expected[cell];
      if (pooledExpected >= 5.0) {
        add(pooledObserved, pooledExpected);
        pooledObserved = pooledExpected = 0.0;
      }
      continue;
    }
    add(observed[cell], expected[cell]);
  }
  if (pooledExpected > 0.0) add(pooledObserved, pooledExpected);
  outcome.freedom = std::max(1, kept - 1);
  outcome.pValue = chiSquareTail(outcome.statistic, outcome.freedom);
  std::ostringstream report;
  report << "chi-square " << outcome.statistic << " with " << outcome.freedom
         << " degrees of freedom: p = " << outcome.pValue << "; " << outcome.outside
         << " samples outside the domain or where the density is 0";
  outcome.report = report.str();
  return outcome;
}

// The angle of (x, y) about the origin as a fraction of a turn, in [0, 1).
inline float turnOf(float x, float y) {
  const float turn = std::atan2(y, x) / (2.0f * kPi);
  return turn < 0.0f ? turn + 1.0f : turn;
}

// A warp of the unit square onto the unit sphere's directions, against its
// density per steradian.
inline ChiSquareOutcome chiSquareOfDirections(const std::function<Vec3(const Vec2&)>& warp,
                                              const std::function<double(const Vec3&)>& density,
                                              const Grid& grid = {}) {
  const auto draw = [&](Rng& rng) -> std::optional<Vec2> {
    const float u = rng.uniform();
    const Vec3 direction = warp({u, rng.uniform()});
    if (std::abs(glm::length(direction) - 1.0f) > 1e-4f) return std::nullopt;
    return Vec2((direction.z + 1.0f) / 2.0f, turnOf(direction.x, direction.y));
  };
  // dw = dz dphi = (2 da) (2 pi db).
  const auto onSquare = [&](double a, double b) {
    const double z = 2.0 * a - 1.0, phi = 2.0 * kPi * b;
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    return 4.0 * kPi *
           density(Vec3(static_cast<float>(radius * std::cos(phi)),
                        static_cast<float>(radius * std::sin(phi)), static_cast<float>(z)));
  };
  return chiSquareOnSquare(draw, onSquare, grid);
}

// A warp of the unit square onto the unit disk, against its density per unit
// of area.
inline ChiSquareOutcome chiSquareOfDiskPoints(const std::function<Vec2(const Vec2&)>& warp,
                                              const std::function<double(const Vec2&)>& density,
                                              const Grid& grid = {}) {
  const auto draw = [&](Rng& rng) -> std::optional<Vec2> {
    const float u = rng.uniform();
    const Vec2 point = warp({u, rng.uniform()});
    const float squared = glm::dot(point, point);
    if (squared > 1.0f + 1e-5f) return std::nullopt;
    return Vec2(std::min(squared, 1.0f), turnOf(point.x, point.y));
  };
  // dA = r dr dangle = (da / 2) (2 pi db).
  const auto onSquare = [&](double a, double b) {
    const double radius = std::sqrt(a), angle = 2.0 * kPi * b;
    return kPi * density(Vec2(static_cast<float>(radius * std::cos(angle)),
                              static_cast<float>(radius * std::sin(angle))));
  };
  return chiSquareOnSquare(draw, onSquare, grid);
}

}  // namespace rise::chi_square_testing
