#include "raster/polygon_coverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "raster/pixel_centres.hpp"

namespace rise {

PixelRect pixelBoundsOf(std::span<const Vec3> corners) {
  Vec2 low(kInfinity), high(-kInfinity);
  for (const Vec3& corner : corners) {
    // It covers nothing rather than everything.
    if (hasNoPlace(corner)) continue;
    low = glm::min(low, Vec2(corner));
    high = glm::max(high, Vec2(corner));
  }
  // The centres x + 1/2 within [low, high].
  return {firstCentreFrom(low.x), firstCentreFrom(low.y), pastLastCentreTo(high.x),
          pastLastCentreTo(high.y)};
}

void PolygonCoverage::reset(std::span<const Vec3> corners) {
  edges_.clear();
  bounds_ = {0, 0, 0, 0};
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& p = corners[i];
    const Vec3& q = corners[nextCorner(i, corners.size())];
    twiceArea += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
  }
  if (twiceArea == 0.0) return;
  // With raster y pointing down, a positive area runs clockwise on the
  // screen, and the inside is where each edge function is positive.
  const float orientation = twiceArea > 0.0 ? 1.0f : -1.0f;

  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 from(corners[i]);
    const Vec2 to(corners[nextCorner(i, corners.size())]);
    if (from == to) continue;
    const bool canonical = std::tie(from.y, from.x) < std::tie(to.y, to.x);
    Edge edge;
    edge.start = canonical ? from : to;
    edge.delta = canonical ? to - from : from - to;
    edge.inside = canonical ? orientation : -orientation;
    // The edge function's gradient points into the polygon.
    const Vec2 inward = edge.inside * Vec2(-edge.delta.y, edge.delta.x);
    edge.ownsCentresOnIt = inward.x > 0.0f || (inward.x == 0.0f && inward.y > 0.0f);
    edges_.push_back(edge);
  }
  bounds_ = pixelBoundsOf(corners);
}

bool PolygonCoverage::covers(const Vec2& point) const {
  for (const Edge& edge : edges_) {
    const float value = edge.function(point);
    if (value < 0.0f || (value == 0.0f && !edge.ownsCentresOnIt)) return false;
  }
  return !edges_.empty();
}

namespace {

template <typename Edge>
std::array<float, 4> atCorners(const Edge& edge, const Vec2& low, const Vec2& high) {
  return {edge.function(low), edge.function(Vec2(high.x, low.y)), edge.function(high),
          edge.function(Vec2(low.x, high.y))};
}

}  // namespace

bool PolygonCoverage::holds(const Vec2& low, const Vec2& high) const {
  return !edges_.empty() && std::all_of(edges_.begin(), edges_.end(), [&](const Edge& edge) {
    const std::array<float, 4> values = atCorners(edge, low, high);
    return std::all_of(values.begin(), values.end(), [](float value) { return value >= 0.0f; });
  });
}

bool PolygonCoverage::edgeSeparates(const Vec2& low, const Vec2& high) const {
  return std::any_of(edges_.begin(), edges_.end(), [&](const Edge& edge) {
    const std::array<float, 4> values = atCorners(edge, low, high);
    return std::all_of(values.begin(), values.end(), [](float value) { return value <= 0.0f; });
  });
}

}  // namespace rise
