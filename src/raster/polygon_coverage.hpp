// Which pixels a convex polygon covers: those whose centres lie inside it,
// with the top-left fill rule for the centres that lie exactly on an edge
// (Direct3D's and OpenGL's rule, see J. Pineda, "A parallel algorithm for
// polygon rasterization", SIGGRAPH 1988, for the edge functions). A centre on
// an edge belongs to the polygon if the edge is a left edge (the polygon lies
// to its right) or a top edge (horizontal, with the polygon below), so that of
// two polygons sharing an edge exactly one covers it: no pixel of a mesh is
// drawn twice or left out.
//
// The rule is exact only if both polygons compute the same value for the
// shared edge at the centre, up to its sign. Each edge is therefore evaluated
// from its endpoints in one canonical order, whichever way the polygon runs
// along it, and negated when needed: floating-point negation is exact.
#pragma once

#include <span>
#include <vector>

#include "core/image.hpp"
#include "core/math.hpp"

namespace rise {

// The smallest rectangle of pixels holding every pixel centre within the
// bounding box of the corners (raster positions in x and y).
PixelRect pixelBoundsOf(std::span<const Vec3> corners);

class PolygonCoverage {
 public:
  PolygonCoverage() = default;
  explicit PolygonCoverage(std::span<const Vec3> corners) { reset(corners); }

  // Takes another polygon (raster positions in x and y), keeping the memory.
  void reset(std::span<const Vec3> corners);

  // A polygon of no area covers nothing.
  bool isEmpty() const { return edges_.empty(); }
  bool covers(const Vec2& point) const;
  // Whether the polygon holds the whole rectangle [low, high], boundary
  // included.
  bool holds(const Vec2& low, const Vec2& high) const;
  // Whether one of its edges has the whole rectangle [low, high] on its outer
  // side or on it: then the polygon covers no point inside the rectangle.
  bool edgeSeparates(const Vec2& low, const Vec2& high) const;

  // The smallest rectangle of pixels holding every centre the polygon covers.
  PixelRect pixelBounds() const { return bounds_; }

  // Calls visit(x, y) for each pixel of `area` whose centre the polygon covers.
  template <typename Visit>
  void forEachPixel(const PixelRect& area, Visit&& visit) const {
    const PixelRect scanned = bounds_.intersection(area);
    for (int y = scanned.y0; y < scanned.y1; ++y)
      for (int x = scanned.x0; x < scanned.x1; ++x)
        if (covers(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f))) visit(x, y);
  }

 private:
  // An edge from `start` along `delta`, in canonical order, and the sign that
  // makes its edge function positive inside the polygon.
  struct Edge {
    Vec2 start;
    Vec2 delta;
    float inside;
    bool ownsCentresOnIt;  // a left or top edge

    float function(const Vec2& p) const {
      return inside * (delta.x * (p.y - start.y) - delta.y * (p.x - start.x));
    }
  };

  std::vector<Edge> edges_;
  PixelRect bounds_{0, 0, 0, 0};
};

}  // namespace rise
