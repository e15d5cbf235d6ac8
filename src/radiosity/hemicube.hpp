// The hemicube of Cohen and Greenberg ("The hemi-cube: a radiosity solution
// for complex environments", SIGGRAPH 1985): the form factors from a point
// to every surface at once, and their visibility with them, by drawing the
// scene with a z-buffer.
//
// Nusselt's analogue: a surface's form factor from a point is the share of
// the unit hemisphere over the point it covers, projected down onto the
// base disc. Any surface that covers the same directions has the same form
// factor, so the hemisphere may be replaced by half a cube around the
// point: a top face along the normal and four half faces around it, each a
// 90-degree perspective view (axis_view.hpp). Each texel of the cube is a
// small surface whose form factor is known in closed form, its delta form
// factor: dA / (pi (x^2 + y^2 + 1)^2) on the top face at (x, y, 1), and
// z dA / (pi (y^2 + z^2 + 1)^2) on a side face at (1, y, z), z up along the
// normal. They sum to 1 over the hemicube. Drawing the surfaces into the
// five faces with a z-buffer that keeps, for each texel, the nearest
// surface's number (an item buffer), and adding each texel's delta form
// factor to the surface it shows, gives every surface's form factor, with
// what hides it already taken away: the surfaces behind it are not seen.
//
// Its errors are those of any z-buffer: a surface smaller than a texel is
// seen or missed by where it falls (aliasing), which a finer cube reduces.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "raster/axis_view.hpp"

namespace rise {

struct HemicubeTriangle {
  std::array<Vec3, 3> corners;
  int receiver;  // the surface it is part of: an index into the form factors
};

class Hemicube {
 public:
  // `resolution`: the texels a side of the top face; an odd one is taken
  // as the even one above it, as the side faces are half as tall.
  explicit Hemicube(int resolution);

  // Adds, to formFactors[r], the form factor from the point (on a surface of
  // unit normal `normal`) to the triangles of receiver r, for every r; the
  // triangles of receiver `ignored` (the point's own surface) are not
  // drawn. Returns the texels that showed a triangle.
  std::uint64_t addFormFactors(const Vec3& point, const Vec3& normal,
                               std::span<const HemicubeTriangle> triangles, int ignored,
                               std::span<float> formFactors);

  // What each of the five faces saw from the last point (the top face,
  // then the sides): by texel, row after row, the receiver (-1: none).
  const std::vector<int>& seen(int face) const { return seen_[static_cast<std::size_t>(face)]; }
  // The rows of a face that lie above the surface: all of the top face's,
  // the upper half of a side's.
  PixelRect above(int face) const;
  float deltaFormFactor(int face, int x, int y) const;

  int resolution() const { return resolution_; }

 private:
  void draw(const Vec3& point, const Vec3& normal, std::span<const HemicubeTriangle> triangles,
            int ignored);

  int resolution_;
  std::array<AxisView, 5> views_;
  std::array<std::vector<float>, 5> depth_;
  std::array<std::vector<int>, 5> seen_;
  std::vector<float> topDelta_, sideDelta_;  // by texel of the top face and of a side's upper half
  PolygonInView polygon_;
};

}  // namespace rise
