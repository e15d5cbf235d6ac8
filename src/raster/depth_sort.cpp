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
// painting order; a transparent piece is blended over what is painted before
// it (raster/transparency.hpp). Cost of a pixel: the times it was painted.
#include "raster/depth_sort.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "raster/bands.hpp"
#include "raster/polygon_clipping.hpp"
#include "raster/polygon_coverage.hpp"
#include "raster/polygon_relations.hpp"
#include "raster/transparency.hpp"
#include "raster/waiting_list.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& DepthSortRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "depth-sort",
      "Newell, Newell and Sancha's depth sort: paint back to front, split what cannot "
      "be sorted",
      "M. E. Newell, R. G. Newell, T. L. Sancha, A solution to the hidden surface "
      "problem, Proceedings of the ACM National Conference, 1972",
      {Effect::Transparency});
  return description;
}

namespace {

// The tests that show that P cannot hide Q, in the order they are tried.
enum Test { kDepth, kXExtent, kYExtent, kBehindPlane, kInFrontOfPlane, kProjection, kTestCount };
constexpr std::array<const char*, kTestCount> kTestNames = {
    "depth", "x_extent", "y_extent", "behind_plane", "front_of_plane", "projection"};
constexpr std::array<const char*, kTestCount> kTestWords = {"the depth extents",
                                                            "the x extents",
                                                            "the y extents",
                                                            "P lies behind Q's plane",
                                                            "Q lies in front of P's plane",
                                                            "the projections"};

struct DepthSortCounters {
  std::array<std::uint64_t, kTestCount> settledBy{};
  std::uint64_t comparisons = 0;
  std::uint64_t moves = 0;
  std::uint64_t splits = 0;
  std::uint64_t unresolved = 0;  // overlaps no split could undo, painted as sorted
};

class DepthSorter {
 public:
  DepthSorter(const ScreenGeometry& screen, const RasterFrame& frame)
      : screen_(screen), frame_(frame), steps_(frame.steps()) {
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
    if (steps_) recordInitialOrder(sorted);
    WaitingList waiting(std::move(sorted), extents_);
    // Refused before the first comparison, not after two billion.
    if (const std::uint64_t pairs = waiting.overlappingPairs(); pairs > kMostDepthSortComparisons)
      throw tooManyComparisons(" (the depths of " + std::to_string(pairs) +
                               " pairs of them overlap)");
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
  // The steps recorded so far, which the painting's follow.
  std::int64_t stepsRecorded() const { return stepsRecorded_; }

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
        if (steps_)
          record(pairStep("move", p, q,
                          "Q cannot be hidden by P (tests 1, 4 or 5 with the roles swapped): Q is "
                          "moved before P and marked"));
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

  RenderLimitError tooManyComparisons(const std::string& found) const {
    return RenderLimitError("depth sort needs more than " +
                            std::to_string(kMostDepthSortComparisons) +
                            " comparisons of pairs of polygons to order this scene's " +
                            std::to_string(screen_.polygons.size()) + " polygons" + found +
                            "; expected a scene it can order within that: render it with "
                            "z-buffer or scanline, or with fewer polygons (--tessellation)");
  }

  bool cannotHide(int p, int q) {
    if (++counters_.comparisons > kMostDepthSortComparisons) throw tooManyComparisons("");
    int settledBy = kTestCount;
    for (int test = 0; test < kTestCount && settledBy == kTestCount; ++test)
      if (passes(static_cast<Test>(test), p, q)) settledBy = test;
    if (settledBy < kTestCount) ++counters_.settledBy[settledBy];
    if (steps_)
      record(pairStep("compare", p, q,
                      settledBy < kTestCount
                          ? std::string("settled by ") + kTestWords[settledBy] + ": P cannot hide Q"
                          : "no test settles it: P may hide Q"));
    return settledBy < kTestCount;
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
    const int front = addPiece(piece, front_);
    if (steps_) record(splitStep(piece, other, behind, front));
    waiting.replace(position, behind, front);
    return true;
  }

  // The steps as a student follows them: numbers name pieces, the polygons
  // and the parts that splits make of them.
  void record(Step step) {
    if (!step.kind.empty()) steps_->record(std::move(step), stepsRecorded_++);
  }

  void recordInitialOrder(const std::vector<int>& sorted) {
    Step step{"sort", "the polygons sorted by their farthest depth, farthest first"};
    step.tables.push_back({"initial order", {"polygon", "face", "farthest depth"}, {}});
    for (int piece : sorted)
      step.tables.back().rows.push_back({static_cast<double>(piece),
                                         static_cast<double>(frame_.sceneFaceOf(faceOf(piece))),
                                         1.0 / extents_[piece].farthest});
    record(std::move(step));
  }

  // A step about P and Q, or none when the recorder does not want it.
  Step pairStep(const char* kind, int p, int q, const std::string& verdict) {
    const Extent& a = extents_[p];
    const Extent& b = extents_[q];
    const PixelRect bounds = pixelBoundsOf(
        std::array{Vec3(glm::min(a.low, b.low), 0.0f), Vec3(glm::max(a.high, b.high), 0.0f)});
    if (!steps_->wantsDetail(bounds)) return {};
    Step step{kind, "P " + std::to_string(p) + " and Q " + std::to_string(q) + ": " + verdict};
    step.values = {{"P", p}, {"Q", q}};
    step.shapes = {outlineOf(cornersOf(p), "polygon"), outlineOf(cornersOf(q), "other")};
    return step;
  }

  Step splitStep(int piece, int other, int behind, int front) {
    Step step = pairStep("split", piece, other,
                         "P straddles Q's plane: split into " + std::to_string(behind) +
                             " (behind) and " + std::to_string(front) + " (in front)");
    if (step.kind.empty()) return step;
    step.shapes = {outlineOf(cornersOf(behind), "behind"), outlineOf(cornersOf(front), "front"),
                   outlineOf(cornersOf(other), "other")};
    return step;
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
  int faceOf(int piece) const { return pieces_.polygons[piece].face; }
  glm::vec4 planeOf(int piece) const { return screen_.faces[pieces_.polygons[piece].face].plane(); }

  const ScreenGeometry& screen_;
  const RasterFrame& frame_;
  StepRecorder* steps_;
  std::int64_t stepsRecorded_ = 0;
  ScreenGeometry pieces_;  // the polygons, then the pieces that splits make
  std::vector<Extent> extents_;
  std::vector<float> tolerances_;  // how near a plane a piece's corners count as on it
  std::vector<bool> marked_;
  std::vector<int> markedThisRound_;
  std::vector<Vec3> front_, behind_;
  DepthSortCounters counters_;
};

// Painting a piece, in the band's part.
Step paintStep(const ScreenGeometry& pieces, int piece, const RasterFrame& frame) {
  const std::span<const Vec3> corners = pieces.cornersOf(pieces.polygons[piece]);
  if (!frame.steps()->wantsDetail(pixelBoundsOf(corners))) return Step("paint", "");
  Step step{"paint", "paint piece " + std::to_string(piece) + " (face " +
                         std::to_string(frame.sceneFaceOf(pieces.polygons[piece].face)) +
                         ") over what is there"};
  step.shapes.push_back(outlineOf(corners, "polygon"));
  return step;
}

// Paints the band's pieces in order; `stepOf` numbers each piece's step.
void paintBand(const ScreenGeometry& pieces, const PixelRect& band, std::span<const int> order,
               std::span<const std::int64_t> stepOf, RasterFrame& frame,
               std::uint64_t& pixelsWritten) {
  PaintedLayers painted(band);
  StepRecorder* const steps = frame.steps();
  PolygonCoverage coverage;
  for (int piece : order) {
    const ScreenPolygon& polygon = pieces.polygons[piece];
    std::optional<Step> step;
    if (steps) step = paintStep(pieces, piece, frame);
    coverage.reset(pieces.cornersOf(polygon));
    const bool transparent = frame.isTransparent(polygon.face);
    coverage.forEachPixel(band, [&](int x, int y) {
      painted.paint(x, y, polygon.face, transparent);
      frame.addCost(x, y, 1.0f);
      if (step) {
        step->writes.push_back(frame.writeOf(x, y, polygon.face, 0.0f));
        if (transparent) step->writes.back().color = painted.shownAt(frame, x, y);
      }
      ++pixelsWritten;
    });
    if (step) steps->record(std::move(*step), stepOf[piece], band.y0);
  }
  painted.show(frame);
}

}  // namespace

void DepthSortRenderer::resolveVisibility(const ScreenGeometry& screen,
                                          const RenderSettings& /*settings*/,
                                          const Workers& workers, RasterFrame& frame,
                                          Stats& stats) const {
  DepthSorter sorter(screen, frame);
  const std::vector<int> order = sorter.paintingOrder();
  std::vector<std::int64_t> stepOf(sorter.pieces().polygons.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    stepOf[order[i]] = sorter.stepsRecorded() + static_cast<std::int64_t>(i);
  const std::uint64_t pixelsWritten = drawInBands<std::uint64_t>(
      workers, sorter.pieces(), order, frame.width(), frame.height(),
      [&](const PixelRect& band, std::span<const int> pieces, std::uint64_t& bandPixels) {
        paintBand(sorter.pieces(), band, pieces, stepOf, frame, bandPixels);
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
