// A square view of the scene from a point along one axis, with a z-buffer of
// its own: what a light sees for its shadow map (shadow_map.hpp), and the
// five faces of radiosity's hemicube (radiosity/hemicube.hpp). Either a
// 90-degree perspective view, a face of the cube around a point, or an
// orthographic view along a direction, from far away.
#pragma once

#include <span>
#include <vector>

#include "core/image.hpp"
#include "core/math.hpp"
#include "raster/polygon_coverage.hpp"

namespace rise {

// Coordinates in the view are (right, up, forward) from its origin; the
// depth of a point is its forward coordinate. Texel (0, 0) is the top left.
struct AxisView {
  Vec3 origin, right, up, forward;
  bool perspective;
  float halfWidth;  // orthographic: half the side of the square seen
  int size;         // texels a side

  Vec3 toView(const Vec3& world) const;
  // The map position of a point given in view coordinates (in front of a
  // perspective view's origin).
  Vec2 toMap(const Vec3& view) const;
  // What is affine across a polygon's image on the map: 1 / depth under
  // perspective, the depth itself under an orthographic view.
  float affineDepth(float depth) const { return perspective ? 1.0f / depth : depth; }
  float depthOfAffine(float affine) const { return perspective ? 1.0f / affine : affine; }
  // The side of a texel in the world at `depth`.
  float texelSize(float depth) const;
  PixelRect whole() const { return {0, 0, size, size}; }
};

// The distance from a perspective view's origin within which it sees
// nothing.
inline constexpr float kAxisViewNear = 1e-4f;

// The six faces of the cube around `centre`, along +x, -x, +y, -y, +z, -z.
std::vector<AxisView> cubeViews(const Vec3& centre, int size);

// The cube face that sees `offset` from its centre: the axis it is longest
// along, on its side (the order of cubeViews).
int cubeFaceOf(const Vec3& offset);

// A convex polygon as a view sees it: clipped to what the view sees (a texel
// of margin beyond its sides), its corners on the map with their affine
// depth, so that the depth at each texel it covers is found by its plane.
class PolygonInView {
 public:
  // Whether any of the polygon, its corners given in the world, is seen,
  // other than edge-on.
  bool project(const AxisView& view, std::span<const Vec3> corners);

  // Calls covered(x, y, depth) for each texel of `area` whose centre the
  // polygon last projected covers.
  template <typename Covered>
  void forEachTexel(const PixelRect& area, Covered&& covered) const {
    coverage_.forEachPixel(area, [&](int x, int y) { covered(x, y, depthAt(x, y)); });
  }

 private:
  float depthAt(int x, int y) const;

  const AxisView* view_ = nullptr;
  std::vector<Vec3> polygon_, inside_, outside_;
  PolygonCoverage coverage_;
  glm::dvec3 corner_{0.0}, normal_{0.0};  // a corner and the plane's normal on the map
};

}  // namespace rise
