// Depth sort, the painter's algorithm made exact (M. E. Newell, R. G. Newell
// and T. L. Sancha, "A solution to the hidden surface problem", Proceedings
// of the ACM National Conference, 1972).
//
// The polygons are sorted by their farthest point and painted back to front,
// each over what is already there. Sorting by one depth is not enough when
// the depth ranges of two polygons overlap, so before P, the next to paint,
// is painted, it is checked against every polygon Q still waiting: P can be
// painted first if one of these tests, cheapest first, shows that it cannot
// hide any part of Q:
//   1. depth: all of P is farther than all of Q;
//   2. x: their screen extents do not overlap in x;
//   3. y: nor in y;
//   4. P lies wholly behind Q's plane (on the side away from the eye);
//   5. Q lies wholly in front of P's plane;
//   6. projection: their images on the screen do not overlap.
// If all fail, P may hide Q. If Q cannot hide P (tests 1, 4 and 5 with the
// roles swapped), Q is moved before P and marked. If Q may hide P too, the two
// interpenetrate, or Q is marked already and the polygons form a cycle of
// overlaps (A over B over C over A): then P is split along Q's plane (or Q
// along P's) into pieces that each lie on one side, and sorting goes on with
// the pieces.
//
// Depths are inverse depths w = 1 / n, and a plane's sides are tested in
// screen space (x, y, w), where planes stay planes. Painting is by the top-left
// fill rule, in bands of scanlines that threads paint in parallel, each in the
// painting order. Cost of a pixel: the times it was painted.
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class DepthSortRenderer final : public VisibleSurfaceRenderer {
 public:
  std::string_view name() const override { return "depth-sort"; }
  std::string_view summary() const override {
    return "Newell, Newell and Sancha's depth sort: paint back to front, split what cannot be "
           "sorted";
  }
  std::string_view citation() const override {
    return "M. E. Newell, R. G. Newell, T. L. Sancha, A solution to the hidden surface problem, "
           "Proceedings of the ACM National Conference, 1972";
  }

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         RenderObserver& observer, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
