// Depth sort, the painter's algorithm made exact, after Newell, Newell and
// Sancha (1972).
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
#include "raster/depth_sort.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "raster/bands.hpp"
#include "raster/polygon_clipping.hpp"
#include "raster/polygon_coverage.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& DepthSortRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "depth-sort",
      "Newell, Newell and Sancha's depth sort: paint back to front, split what cannot "
      "be sorted",
      "M. E. Newell, R. G. Newell, T. L. Sancha, A solution to the hidden surface "
      "problem, Proceedings of the ACM National Conference, 1972");
  return description;
}

namespace {

// The tests that show that P cannot hide Q, in the order they are tried.
enum Test { kDepth, kXExtent, kYExtent, kBehindPlane, kInFrontOfPlane, kProjection, kTestCount };
constexpr std::array<const char*, kTestCount> kTestNames = {
    "depth", "x_extent", "y_extent", "behind_plane", "front_of_plane", "projection"};

// Corners this close to a plane, relative to the polygon's nearest inverse
// depth, are on it: the corners two faces share lie on both faces' planes,
// up to rounding.
constexpr float kPlaneTolerance = 1e-5f;
// Images overlapping by less than this, in pixels, only touch.
constexpr float kOverlapTolerance = 1e-4f;

struct DepthSortCounters {
  std::array<std::uint64_t, kTestCount> settledBy{};
  std::uint64_t comparisons = 0;
  std::uint64_t moves = 0;
  std::uint64_t splits = 0;
  std::uint64_t unresolved = 0;  // overlaps no split could undo, painted as sorted
};

// A polygon's screen extent and depth range (inverse depths: `farthest` is
// the smallest w).
struct Extent {
  Vec2 low, high;
  float farthest, nearest;
};

Extent extentOf(std::span<const Vec3> corners) {
  Extent extent{Vec2(kInfinity), Vec2(-kInfinity), kInfinity, -kInfinity};
  for (const Vec3& corner : corners) {
    extent.low = glm::min(extent.low, Vec2(corner));
    extent.high = glm::max(extent.high, Vec2(corner));
    extent.farthest = std::min(extent.farthest, corner.z);
    extent.nearest = std::max(extent.nearest, corner.z);
  }
  return extent;
}

// Where the corners lie from a plane in screen space: wholly behind it (none
// in front), wholly in front (none behind), or both ways.
struct PlaneSides {
  bool someInFront = false;
  bool someBehind = false;
};

// `tolerance` is the polygon's own: the one its split uses too, so that a
// piece of a split never lies on both sides of the plane that cut it.
PlaneSides planeSides(std::span<const Vec3> corners, const glm::vec4& plane, float tolerance) {
  PlaneSides sides;
  for (const Vec3& corner : corners) {
    const float distance = signedDistance(plane, corner);
    sides.someInFront |= distance > tolerance;
    sides.someBehind |= distance < -tolerance;
  }
  return sides;
}

// Whether an edge of `a`, as a separating axis, keeps the two convex images
// apart.
bool separatedByAnEdgeOf(std::span<const Vec3> a, std::span<const Vec3> b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 edge = Vec2(a[(i + 1) % a.size()]) - Vec2(a[i]);
    const float length = glm::length(edge);
    if (length == 0.0f) continue;
    const Vec2 axis = Vec2(-edge.y, edge.x) / length;
    float lowA = kInfinity, highA = -kInfinity, lowB = kInfinity, highB = -kInfinity;
    for (const Vec3& corner : a) {
      lowA = std::min(lowA, glm::dot(axis, Vec2(corner)));
      highA = std::max(highA, glm::dot(axis, Vec2(corner)));
    }
    for (const Vec3& corner : b) {
      lowB = std::min(lowB, glm::dot(axis, Vec2(corner)));
      highB = std::max(highB, glm::dot(axis, Vec2(corner)));
    }
    if (highA <= lowB + kOverlapTolerance || highB <= lowA + kOverlapTolerance) return true;
  }
  return false;
}

bool imagesOverlap(std::span<const Vec3> a, std::span<const Vec3> b) {
  return !separatedByAnEdgeOf(a, b) && !separatedByAnEdgeOf(b, a);
}

// The polygons waiting to be painted, the next at the front. Behind the
// polygons moved to the front or cut there, the rest stays sorted by farthest
// depth, so that the search for polygons the front one may hide can stop at
// the first of them that lies wholly nearer.
class WaitingList {
 public:
  WaitingList(std::vector<int> sorted, const std::vector<Extent>& extents)
      : list_(std::move(sorted)), extents_(extents) {}

  bool isEmpty() const { return head_ == list_.size(); }
  int front() const { return list_[head_]; }
  // Positions run from the front, 0, to size() - 1.
  std::size_t size() const { return list_.size() - head_; }
  int at(std::size_t position) const { return list_[head_ + position]; }
  bool isSortedAt(std::size_t position) const { return head_ + position >= sortedFrom_; }
  std::size_t find(int piece) const {
    return static_cast<std::size_t>(std::find(list_.begin() + head_, list_.end(), piece) -
                                    list_.begin()) -
           head_;
  }

  void popFront() { sortedFrom_ = std::max(sortedFrom_, ++head_); }

  void moveToFront(std::size_t position) {
    const auto moved = list_.begin() + static_cast<std::ptrdiff_t>(head_ + position);
    if (isSortedAt(position)) ++sortedFrom_;
    std::rotate(list_.begin() + static_cast<std::ptrdiff_t>(head_), moved, moved + 1);
  }

  // Puts two pieces in place of the polygon at `position`: at the front, both
  // at the front; in the sorted part, each where its depth sorts it.
  void replace(std::size_t position, int first, int second) {
    const std::size_t index = head_ + position;
    if (position == 0 || !isSortedAt(position)) {
      list_[index] = first;
      list_.insert(list_.begin() + static_cast<std::ptrdiff_t>(index) + 1, second);
      sortedFrom_ = std::max(sortedFrom_ + 1, index + 2);
      return;
    }
    list_.erase(list_.begin() + static_cast<std::ptrdiff_t>(index));
    for (int piece : {first, second}) {
      const auto place = std::upper_bound(
          list_.begin() + static_cast<std::ptrdiff_t>(sortedFrom_), list_.end(), piece,
          [&](int a, int b) { return extents_[a].farthest < extents_[b].farthest; });
      list_.insert(place, piece);
    }
  }

 private:
  std::vector<int> list_;
  const std::vector<Extent>& extents_;
  std::size_t head_ = 0;
  std::size_t sortedFrom_ = 0;
};

class DepthSorter {
 public:
  explicit DepthSorter(const ScreenGeometry& screen) : screen_(screen) {
    pieces_.corners = screen.corners;
    pieces_.polygons = screen.polygons;
    for (const ScreenPolygon& polygon : pieces_.polygons) {
      extents_.push_back(extentOf(pieces_.cornersOf(polygon)));
      tolerances_.push_back(kPlaneTolerance * extents_.back().nearest);
    }
    marked_.assign(pieces_.polygons.size(), false);
  }

  // The pieces (whole polygons or parts of split ones) in painting order.
  std::vector<int> paintingOrder() {
    std::vector<int> sorted(pieces_.polygons.size());
    std::iota(sorted.begin(), sorted.end(), 0);
    std::stable_sort(sorted.begin(), sorted.end(),
                     [&](int a, int b) { return extents_[a].farthest < extents_[b].farthest; });
    WaitingList waiting(std::move(sorted), extents_);
    std::vector<int> order;
    while (!waiting.isEmpty()) {
      if (!resolveFront(waiting)) continue;
      order.push_back(waiting.front());
      waiting.popFront();
      // A cycle is a polygon moved twice before anything could be painted.
      for (int piece : markedThisRound_) marked_[piece] = false;
      markedThisRound_.clear();
    }
    return order;
  }

  const ScreenGeometry& pieces() const { return pieces_; }
  const DepthSortCounters& counters() const { return counters_; }

 private:
  // Checks the front polygon against the polygons after it. Returns true
  // when it can be painted; otherwise it has changed the list (moved a
  // polygon to the front, or split one) and the new front must be checked.
  bool resolveFront(WaitingList& waiting) {
    const int p = waiting.front();
    for (std::size_t k = 1; k < waiting.size(); ++k) {
      const int q = waiting.at(k);
      // Sorted polygons from here on lie wholly nearer than P.
      if (waiting.isSortedAt(k) && extents_[p].nearest <= extents_[q].farthest) break;
      if (cannotHide(p, q)) continue;
      if (!marked_[q] && cannotHideByDepthOrPlanes(q, p)) {
        // Q must be painted before P.
        ++counters_.moves;
        mark(q);
        waiting.moveToFront(k);
        return false;
      }
      if (split(p, q, waiting, 0) || split(q, p, waiting, k) ||
          (marked_[q] && splitAcrossCycle(p, waiting)))
        return false;
      ++counters_.unresolved;
    }
    return true;
  }

  // P and Q close a cycle of overlaps, but each lies wholly on one side of
  // the other's plane: cut the cycle at another of its polygons, splitting P
  // along its plane or it along P's.
  bool splitAcrossCycle(int p, WaitingList& waiting) {
    // Splitting marks pieces, which joins them to the cycle: walk a copy.
    const std::vector<int> cycle = markedThisRound_;
    for (int other : cycle) {
      const std::size_t position = waiting.find(other);
      if (position == 0 || position >= waiting.size()) continue;
      if (split(p, other, waiting, 0) || split(other, p, waiting, position)) return true;
    }
    return false;
  }

  bool cannotHide(int p, int q) {
    if (++counters_.comparisons > kMostDepthSortComparisons)
      throw RenderLimitError("depth sort needs more than " +
                             std::to_string(kMostDepthSortComparisons) +
                             " comparisons of pairs of polygons to order this scene's " +
                             std::to_string(screen_.polygons.size()) +
                             " polygons; expected a scene it can order within that: render it with "
                             "z-buffer or scanline, or "
                             "with fewer polygons (--tessellation)");
    for (int test = 0; test < kTestCount; ++test) {
      if (!passes(static_cast<Test>(test), p, q)) continue;
      ++counters_.settledBy[test];
      return true;
    }
    return false;
  }

  // Whether the test shows that p cannot hide q.
  bool passes(Test test, int p, int q) const {
    const Extent& a = extents_[p];
    const Extent& b = extents_[q];
    switch (test) {
      case kDepth:
        return a.nearest <= b.farthest;
      case kXExtent:
        return a.high.x <= b.low.x || b.high.x <= a.low.x;
      case kYExtent:
        return a.high.y <= b.low.y || b.high.y <= a.low.y;
      case kBehindPlane:
        return !planeSides(cornersOf(p), planeOf(q), tolerances_[p]).someInFront;
      case kInFrontOfPlane:
        return !planeSides(cornersOf(q), planeOf(p), tolerances_[q]).someBehind;
      case kProjection:
        return !imagesOverlap(cornersOf(p), cornersOf(q));
      case kTestCount:
        break;
    }
    return false;
  }

  // Tests 1, 4 and 5: the others do not depend on the order of the two.
  bool cannotHideByDepthOrPlanes(int p, int q) const {
    return passes(kDepth, p, q) || passes(kBehindPlane, p, q) || passes(kInFrontOfPlane, p, q);
  }

  void mark(int piece) {
    marked_[piece] = true;
    markedThisRound_.push_back(piece);
  }

  // Splits the piece at `position` in the list along `other`'s plane if it
  // lies on both sides of it, the part behind the plane first. The pieces
  // keep the piece's tolerance, so that each lies on one side of that plane
  // for good (a piece is never cut twice by one plane), and its mark: as
  // Newell's polygons, a piece of one that was moved is split again, never
  // moved again, until something is painted.
  bool split(int piece, int other, WaitingList& waiting, std::size_t position) {
    const std::span<const Vec3> corners = cornersOf(piece);
    const float tolerance = tolerances_[piece];
    if (const PlaneSides sides = planeSides(corners, planeOf(other), tolerance);
        !(sides.someInFront && sides.someBehind))
      return false;
    const std::vector<Vec3> copy(corners.begin(), corners.end());
    splitPolygon(copy, planeOf(other), tolerance, front_, behind_);
    // Where a crossing rounds onto a corner off the plane (the plane nearly
    // along the edge), the cut cannot part the sides: no split.
    if (planeSides(behind_, planeOf(other), tolerance).someInFront ||
        planeSides(front_, planeOf(other), tolerance).someBehind)
      return false;
    if (++counters_.splits > kMostDepthSortSplits)
      throw RenderLimitError("depth sort needs more than " + std::to_string(kMostDepthSortSplits) +
                             " splits to order this scene's " +
                             std::to_string(screen_.polygons.size()) +
                             " polygons; expected a scene it can order within that: render it "
                             "with z-buffer or scanline");
    const int behind = addPiece(piece, behind_);
    waiting.replace(position, behind, addPiece(piece, front_));
    return true;
  }

  int addPiece(int parent, std::span<const Vec3> corners) {
    const int piece = pieces_.addPolygon(pieces_.polygons[parent].face, corners);
    extents_.push_back(extentOf(corners));
    tolerances_.push_back(tolerances_[parent]);
    marked_.push_back(false);
    if (marked_[parent]) mark(piece);
    return piece;
  }

  std::span<const Vec3> cornersOf(int piece) const {
    return pieces_.cornersOf(pieces_.polygons[piece]);
  }
  glm::vec4 planeOf(int piece) const { return screen_.faces[pieces_.polygons[piece].face].plane(); }

  const ScreenGeometry& screen_;
  ScreenGeometry pieces_;  // the polygons, then the pieces that splits make
  std::vector<Extent> extents_;
  std::vector<float> tolerances_;  // how near a plane a piece's corners count as on it
  std::vector<bool> marked_;
  std::vector<int> markedThisRound_;
  std::vector<Vec3> front_, behind_;
  DepthSortCounters counters_;
};

void paintBand(const ScreenGeometry& pieces, const PixelRect& band, std::span<const int> order,
               RasterFrame& frame, std::uint64_t& pixelsWritten) {
  std::vector<int> faces(static_cast<std::size_t>(band.width()) * band.height(), -1);
  const auto at = [&](int x, int y) -> int& {
    return faces[static_cast<std::size_t>(y - band.y0) * band.width() + x - band.x0];
  };
  PolygonCoverage coverage;
  for (int piece : order) {
    const ScreenPolygon& polygon = pieces.polygons[piece];
    coverage.reset(pieces.cornersOf(polygon));
    coverage.forEachPixel(band, [&](int x, int y) {
      at(x, y) = polygon.face;
      frame.addCost(x, y, 1.0f);
      ++pixelsWritten;
    });
  }
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x)
      if (at(x, y) >= 0) frame.setVisible(x, y, at(x, y));
}

}  // namespace

void DepthSortRenderer::resolveVisibility(const ScreenGeometry& screen, const Workers& workers,
                                          RasterFrame& frame, Stats& stats) const {
  DepthSorter sorter(screen);
  const std::vector<int> order = sorter.paintingOrder();
  const std::uint64_t pixelsWritten = drawInBands<std::uint64_t>(
      workers, sorter.pieces(), order, frame.width(), frame.height(),
      [&](const PixelRect& band, std::span<const int> pieces, std::uint64_t& bandPixels) {
        paintBand(sorter.pieces(), band, pieces, frame, bandPixels);
      });

  const DepthSortCounters& counters = sorter.counters();
  stats.add("pixels_written", static_cast<double>(pixelsWritten));
  stats.add("comparisons", static_cast<double>(counters.comparisons));
  for (int test = 0; test < kTestCount; ++test)
    stats.add(std::string("settled_by_") + kTestNames[test],
              static_cast<double>(counters.settledBy[test]));
  stats.add("moves", static_cast<double>(counters.moves));
  stats.add("splits", static_cast<double>(counters.splits));
  stats.add("unresolved_overlaps", static_cast<double>(counters.unresolved));
  stats.add("polygons_painted", static_cast<double>(order.size()));
}

}  // namespace rise
