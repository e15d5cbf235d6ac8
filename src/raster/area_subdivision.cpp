// Area subdivision, after Warnock (1969).
//
// Divide and conquer over the screen: a window, at first the whole image, is
// drawn at once if what it shows is simple; otherwise it is cut into four
// quadrants, each handled the same way. Each polygon stands to a window in
// one of four relations:
//   surrounding   it holds the whole window;
//   intersecting  it crosses the window's border;
//   contained     it lies wholly inside the window;
//   disjoint      it covers none of it.
// A window is simple, and drawn, when
//   - every polygon is disjoint from it: it shows the background;
//   - one polygon alone is not disjoint: it is scan-converted in the window
//     over the background;
//   - a surrounding polygon is in front of all the others everywhere in the
//     window (its farthest depth there nearer than their nearest): it fills
//     the window;
//   - the window is a single pixel: the polygons covering the pixel's centre
//     are compared in depth there, and the nearest is drawn.
// Only the polygons not disjoint from a window are handed to its quadrants.
//
// A transparent polygon (raster/transparency.hpp) hides nothing: it never
// fills a window as the surrounder in front, so that a window it reaches
// into is settled only by it alone (blended over the background) or at the
// pixel, where the nearest opaque polygon is drawn and the transparent ones
// in front of it are blended over it, farthest first.
//
// Depths are inverse depths w = 1 / n, affine across a polygon's image, so
// their extremes over a window lie at its corners. The windows waiting to be
// examined are shared among threads. Cost of a pixel:
// the classifications made for the windows that hold it, each window's shared
// among its pixels, plus the depth tests made at the pixel.
#include "raster/area_subdivision.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "raster/polygon_coverage.hpp"
#include "raster/transparency.hpp"

namespace rise {

const AlgorithmDescription& AreaSubdivisionRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "area-subdivision",
      "Warnock's area subdivision: quarter the screen until each window is simple",
      "J. E. Warnock, A hidden-surface algorithm for computer generated half-tone "
      "pictures, University of Utah, TR 4-15, 1969",
      {Effect::Transparency});
  return description;
}

namespace {

enum Relation { kSurrounding, kIntersecting, kContained, kDisjoint, kRelationCount };
constexpr std::array<const char*, kRelationCount> kRelationNames = {"surrounding", "intersecting",
                                                                    "contained", "disjoint"};

struct SubdivisionCounters {
  std::array<std::uint64_t, kRelationCount> relations{};
  std::uint64_t windows = 0;
  std::uint64_t subdivisions = 0;
  std::uint64_t emptyWindows = 0;
  std::uint64_t singlePolygonWindows = 0;
  std::uint64_t surrounderInFrontWindows = 0;
  std::uint64_t pixelWindows = 0;
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  std::uint64_t blends = 0;

  SubdivisionCounters& operator+=(const SubdivisionCounters& other) {
    for (int relation = 0; relation < kRelationCount; ++relation)
      relations[relation] += other.relations[relation];
    windows += other.windows;
    subdivisions += other.subdivisions;
    emptyWindows += other.emptyWindows;
    singlePolygonWindows += other.singlePolygonWindows;
    surrounderInFrontWindows += other.surrounderInFrontWindows;
    pixelWindows += other.pixelWindows;
    depthTests += other.depthTests;
    pixelsWritten += other.pixelsWritten;
    blends += other.blends;
    return *this;
  }
};

// A window waiting to be examined, with the polygons not disjoint from its
// parent: the only ones that can reach into it. Its place in the quadtree,
// `path`, numbers the windows in the order a single examiner going depth
// first would take them: a window before its quadrants, quadrants in order.
struct Window {
  PixelRect area;
  std::vector<int> candidates;
  std::int64_t path = 0;
  int level = 0;
};

// Quadrant q of the window at `path`, `level`: one base-5 digit a level,
// 1 to 4, most significant first, so that numbers sort depth first.
constexpr int kDeepestLevel = 26;
std::int64_t quadrantPath(std::int64_t path, int level, int q) {
  std::int64_t unit = 1;
  for (int below = level + 1; below < kDeepestLevel; ++below) unit *= 5;
  return path + (q + 1) * unit;
}

// How Warnock settled a window, or that it could not.
enum class Verdict { Empty, OnePolygon, SurrounderInFront, Pixel, Quartered };

const char* describe(Verdict verdict) {
  switch (verdict) {
    case Verdict::Empty:
      return "every polygon is disjoint from it: background";
    case Verdict::OnePolygon:
      return "one polygon alone reaches into it: drawn (or, transparent, blended) over the "
             "background";
    case Verdict::SurrounderInFront:
      return "a surrounding polygon is in front of all the others: it fills the window";
    case Verdict::Pixel:
      return "a single pixel: the nearest opaque polygon at its centre is drawn, the "
             "transparent ones in front of it blended over it";
    case Verdict::Quartered:
      return "not simple: quartered";
  }
  return "?";
}

Vec2 pixelCentre(int x, int y) {
  return {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f};
}

class Subdivision {
 public:
  Subdivision(const ScreenGeometry& screen, RasterFrame& frame) : screen_(screen), frame_(frame) {
    coverages_.reserve(screen.polygons.size());
    for (const ScreenPolygon& polygon : screen.polygons) {
      const std::span<const Vec3> corners = screen.cornersOf(polygon);
      coverages_.emplace_back(corners);
      Vec2 low(kInfinity), high(-kInfinity);
      float nearest = -kInfinity;
      for (const Vec3& corner : corners) {
        low = glm::min(low, Vec2(corner));
        high = glm::max(high, Vec2(corner));
        nearest = std::max(nearest, corner.z);
      }
      extents_.push_back({low, high});
      nearest_.push_back(nearest);
      transparent_.push_back(frame.isTransparent(polygon.face));
    }
  }

  // Draws the window if what it shows is simple, or else hands back its
  // quadrants in `quadrants`, to be examined in turn.
  void examine(const Window& examined, SubdivisionCounters& counters,
               std::vector<Window>& quadrants) const {
    const PixelRect& window = examined.area;
    const std::vector<int>& candidates = examined.candidates;
    ++counters.windows;
    const Vec2 low(static_cast<float>(window.x0), static_cast<float>(window.y0));
    const Vec2 high(static_cast<float>(window.x1), static_cast<float>(window.y1));
    std::vector<int> present;
    StepRecorder* const steps = frame_.steps();
    std::vector<Relation> relations;  // kept for the step alone
    int frontSurrounder = -1;
    for (int polygon : candidates) {
      const Relation relation = classify(polygon, low, high);
      ++counters.relations[relation];
      if (steps) relations.push_back(relation);
      if (relation == kDisjoint) continue;
      present.push_back(polygon);
      if (relation == kSurrounding && !transparent_[polygon] &&
          (frontSurrounder < 0 ||
           farthestIn(polygon, low, high) > farthestIn(frontSurrounder, low, high)))
        frontSurrounder = polygon;
    }
    chargeToPixels(window, static_cast<float>(candidates.size()));

    Verdict verdict = Verdict::Quartered;
    if (present.empty()) {
      verdict = Verdict::Empty;
      ++counters.emptyWindows;
    } else if (present.size() == 1) {
      verdict = Verdict::OnePolygon;
      ++counters.singlePolygonWindows;
      coverages_[present[0]].forEachPixel(window,
                                          [&](int x, int y) { draw(x, y, present[0], counters); });
    } else if (frontSurrounder >= 0 && isInFrontOfAll(frontSurrounder, present, low, high)) {
      verdict = Verdict::SurrounderInFront;
      ++counters.surrounderInFrontWindows;
      for (int y = window.y0; y < window.y1; ++y)
        for (int x = window.x0; x < window.x1; ++x) draw(x, y, frontSurrounder, counters);
    } else if (window.x1 - window.x0 == 1 && window.y1 - window.y0 == 1) {
      verdict = Verdict::Pixel;
      ++counters.pixelWindows;
      resolvePixel(window.x0, window.y0, present, counters);
    } else {
      ++counters.subdivisions;
      int q = 0;
      for (const PixelRect& quadrant : quadrantsOf(window))
        quadrants.push_back({quadrant, present, quadrantPath(examined.path, examined.level, q++),
                             examined.level + 1});
    }
    if (steps) steps->record(windowStep(examined, relations, verdict), examined.path);
  }

 private:
  struct Extent {
    Vec2 low, high;
  };

  Relation classify(int polygon, const Vec2& low, const Vec2& high) const {
    const Extent& extent = extents_[polygon];
    if (extent.high.x <= low.x || extent.low.x >= high.x || extent.high.y <= low.y ||
        extent.low.y >= high.y || coverages_[polygon].edgeSeparates(low, high))
      return kDisjoint;
    if (coverages_[polygon].holds(low, high)) return kSurrounding;
    if (extent.low.x >= low.x && extent.high.x <= high.x && extent.low.y >= low.y &&
        extent.high.y <= high.y)
      return kContained;
    return kIntersecting;
  }

  // The polygon's plane at the window's corners.
  std::array<float, 4> planeAtCorners(int polygon, const Vec2& low, const Vec2& high) const {
    const ScreenFace& face = screen_.faces[screen_.polygons[polygon].face];
    return {face.inverseDepthAt(low), face.inverseDepthAt(Vec2(high.x, low.y)),
            face.inverseDepthAt(high), face.inverseDepthAt(Vec2(low.x, high.y))};
  }

  // The smallest w of a surrounding polygon over the window: its farthest.
  float farthestIn(int polygon, const Vec2& low, const Vec2& high) const {
    const std::array<float, 4> w = planeAtCorners(polygon, low, high);
    return *std::min_element(w.begin(), w.end());
  }

  // No point of another polygon in the window is as near as the surrounder's
  // farthest: the other's plane is no nearer than at the window's corners,
  // and the polygon no nearer than at its own.
  bool isInFrontOfAll(int surrounder, const std::vector<int>& present, const Vec2& low,
                      const Vec2& high) const {
    const float farthest = farthestIn(surrounder, low, high);
    return std::all_of(present.begin(), present.end(), [&](int other) {
      if (other == surrounder) return true;
      const std::array<float, 4> w = planeAtCorners(other, low, high);
      const float nearest = std::min(*std::max_element(w.begin(), w.end()), nearest_[other]);
      return farthest > nearest;
    });
  }

  // The nearest opaque polygon covering the centre (of equal depths, the
  // first), and the transparent ones in front of it blended over it.
  void resolvePixel(int x, int y, const std::vector<int>& present,
                    SubdivisionCounters& counters) const {
    const Vec2 centre = pixelCentre(x, y);
    int nearest = -1;
    float nearestInverseDepth = 0.0f;
    std::vector<std::pair<float, int>> transparent;  // inverse depth, polygon
    for (int polygon : present) {
      if (!coverages_[polygon].covers(centre)) continue;
      ++counters.depthTests;
      frame_.addCost(x, y, 1.0f);
      const float inverseDepth =
          screen_.faces[screen_.polygons[polygon].face].inverseDepthAt(centre);
      if (transparent_[polygon]) {
        transparent.emplace_back(inverseDepth, polygon);
      } else if (inverseDepth > nearestInverseDepth) {
        nearest = polygon;
        nearestInverseDepth = inverseDepth;
      }
    }
    std::stable_sort(transparent.begin(), transparent.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<int> inFront;
    for (const auto& [inverseDepth, polygon] : transparent)
      if (inverseDepth > nearestInverseDepth) inFront.push_back(screen_.polygons[polygon].face);
    showAt(x, y, nearest, inFront, counters);
  }

  void draw(int x, int y, int polygon, SubdivisionCounters& counters) const {
    const int face = screen_.polygons[polygon].face;
    if (transparent_[polygon])
      showAt(x, y, -1, std::span<const int>(&face, 1), counters);
    else
      showAt(x, y, polygon, {}, counters);
  }

  // The opaque polygon `opaque` (-1: the background) and the transparent
  // faces over it, farthest first.
  void showAt(int x, int y, int opaque, std::span<const int> over,
              SubdivisionCounters& counters) const {
    if (opaque < 0 && over.empty()) return;
    ++counters.pixelsWritten;
    counters.blends +=
        showLayers(frame_, x, y, opaque >= 0 ? screen_.polygons[opaque].face : -1, over);
  }

  void chargeToPixels(const PixelRect& window, float work) const {
    const float share =
        work / static_cast<float>((window.x1 - window.x0) * (window.y1 - window.y0));
    for (int y = window.y0; y < window.y1; ++y)
      for (int x = window.x0; x < window.x1; ++x) frame_.addCost(x, y, share);
  }

  // The window as a student follows it: its polygons classified, and how
  // it was settled or why it was quartered.
  static Step windowStep(const Window& window, const std::vector<Relation>& relations,
                         Verdict verdict) {
    const PixelRect& area = window.area;
    Step step;
    step.kind = "window";
    int counts[kRelationCount] = {};
    StepTable classified{"polygons classified", {"polygon", "relation"}, {}};
    for (std::size_t i = 0; i < relations.size(); ++i) {
      ++counts[relations[i]];
      if (relations[i] != kDisjoint)
        classified.rows.push_back(
            {static_cast<double>(window.candidates[i]), kRelationNames[relations[i]]});
    }
    step.text = "window " + std::to_string(area.x0) + "," + std::to_string(area.y0) + " " +
                std::to_string(area.width()) + "x" + std::to_string(area.height()) + ": " +
                std::to_string(counts[kSurrounding]) + " surrounding, " +
                std::to_string(counts[kIntersecting]) + " intersecting, " +
                std::to_string(counts[kContained]) + " contained, " +
                std::to_string(counts[kDisjoint]) + " disjoint; " + describe(verdict);
    step.values = {{"level", window.level}};
    step.tables.push_back(std::move(classified));
    step.shapes.push_back({StepShape::Kind::Rectangle,
                           "window",
                           {Vec2(static_cast<float>(area.x0), static_cast<float>(area.y0)),
                            Vec2(static_cast<float>(area.x1), static_cast<float>(area.y1))}});
    if (verdict != Verdict::Quartered) step.settled.push_back(area);
    return step;
  }

  static std::vector<PixelRect> quadrantsOf(const PixelRect& window) {
    const int middleX = (window.x0 + window.x1) / 2;
    const int middleY = (window.y0 + window.y1) / 2;
    std::vector<PixelRect> parts;
    for (const PixelRect& part : {PixelRect{window.x0, window.y0, middleX, middleY},
                                  PixelRect{middleX, window.y0, window.x1, middleY},
                                  PixelRect{window.x0, middleY, middleX, window.y1},
                                  PixelRect{middleX, middleY, window.x1, window.y1}})
      if (!part.isEmpty()) parts.push_back(part);
    return parts;
  }

  const ScreenGeometry& screen_;
  RasterFrame& frame_;
  std::vector<PolygonCoverage> coverages_;
  std::vector<Extent> extents_;
  std::vector<float> nearest_;  // each polygon's largest w
  std::vector<bool> transparent_;
};

}  // namespace

void AreaSubdivisionRenderer::resolveVisibility(const ScreenGeometry& screen,
                                                const RenderSettings& /*settings*/,
                                                const Workers& workers, RasterFrame& frame,
                                                Stats& stats) const {
  const Subdivision subdivision(screen, frame);
  std::vector<int> all(screen.polygons.size());
  std::iota(all.begin(), all.end(), 0);
  // The windows waiting to be examined, at first the whole screen; the
  // workers take them in turn, as a single examiner would take them from
  // Warnock's stack.
  const SubdivisionCounters total = workers.drain<Window, SubdivisionCounters>(
      {Window{{0, 0, frame.width(), frame.height()}, std::move(all)}},
      [&](const Window& window, SubdivisionCounters& counters, std::vector<Window>& quadrants) {
        subdivision.examine(window, counters, quadrants);
      });
  stats.add("depth_tests", static_cast<double>(total.depthTests));
  stats.add("pixels_written", static_cast<double>(total.pixelsWritten));
  stats.add("transparent_blends", static_cast<double>(total.blends));
  stats.add("windows", static_cast<double>(total.windows));
  stats.add("subdivisions", static_cast<double>(total.subdivisions));
  stats.add("windows_empty", static_cast<double>(total.emptyWindows));
  stats.add("windows_one_polygon", static_cast<double>(total.singlePolygonWindows));
  stats.add("windows_surrounder_in_front", static_cast<double>(total.surrounderInFrontWindows));
  stats.add("windows_pixel", static_cast<double>(total.pixelWindows));
  for (int relation = 0; relation < kRelationCount; ++relation)
    stats.add(std::string("classified_") + kRelationNames[relation],
              static_cast<double>(total.relations[relation]));
}

}  // namespace rise
