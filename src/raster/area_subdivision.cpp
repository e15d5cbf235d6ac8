#include "raster/area_subdivision.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "raster/polygon_coverage.hpp"
#include "render/tiles.hpp"

namespace rise {
namespace {

enum Relation { kSurrounding, kIntersecting, kContained, kDisjoint, kRelationCount };
constexpr std::array<const char*, kRelationCount> kRelationNames = {"surrounding", "intersecting",
                                                                    "contained", "disjoint"};

// The windows this many levels down are shared among threads.
constexpr int kParallelLevel = 3;

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
    return *this;
  }
};

// A window still to be subdivided, and the polygons not disjoint from its
// parent.
struct PendingWindow {
  PixelRect window;
  std::vector<int> candidates;
};

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
    }
  }

  // Handles `window`; windows reaching `stopLevel` are left in `pending`.
  void subdivide(const PixelRect& window, const std::vector<int>& candidates, int level,
                 int stopLevel, std::vector<PendingWindow>& pending,
                 SubdivisionCounters& counters) const {
    if (level == stopLevel) {
      pending.push_back({window, candidates});
      return;
    }
    ++counters.windows;
    const Vec2 low(static_cast<float>(window.x0), static_cast<float>(window.y0));
    const Vec2 high(static_cast<float>(window.x1), static_cast<float>(window.y1));
    std::vector<int> present;
    int frontSurrounder = -1;
    for (int polygon : candidates) {
      const Relation relation = classify(polygon, low, high);
      ++counters.relations[relation];
      if (relation == kDisjoint) continue;
      present.push_back(polygon);
      if (relation == kSurrounding &&
          (frontSurrounder < 0 ||
           farthestIn(polygon, low, high) > farthestIn(frontSurrounder, low, high)))
        frontSurrounder = polygon;
    }
    chargeToPixels(window, static_cast<float>(candidates.size()));

    if (present.empty()) {
      ++counters.emptyWindows;
    } else if (present.size() == 1) {
      ++counters.singlePolygonWindows;
      coverages_[present[0]].forEachPixel(window,
                                          [&](int x, int y) { draw(x, y, present[0], counters); });
    } else if (frontSurrounder >= 0 && isInFrontOfAll(frontSurrounder, present, low, high)) {
      ++counters.surrounderInFrontWindows;
      for (int y = window.y0; y < window.y1; ++y)
        for (int x = window.x0; x < window.x1; ++x) draw(x, y, frontSurrounder, counters);
    } else if (window.x1 - window.x0 == 1 && window.y1 - window.y0 == 1) {
      ++counters.pixelWindows;
      resolvePixel(window.x0, window.y0, present, counters);
    } else {
      ++counters.subdivisions;
      for (const PixelRect& quadrant : quadrants(window))
        subdivide(quadrant, present, level + 1, stopLevel, pending, counters);
    }
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

  // The nearest polygon covering the centre; of equal depths, the first.
  void resolvePixel(int x, int y, const std::vector<int>& present,
                    SubdivisionCounters& counters) const {
    const Vec2 centre = pixelCentre(x, y);
    int nearest = -1;
    float nearestInverseDepth = 0.0f;
    for (int polygon : present) {
      if (!coverages_[polygon].covers(centre)) continue;
      ++counters.depthTests;
      frame_.addCost(x, y, 1.0f);
      const float inverseDepth =
          screen_.faces[screen_.polygons[polygon].face].inverseDepthAt(centre);
      if (inverseDepth <= nearestInverseDepth) continue;
      nearest = polygon;
      nearestInverseDepth = inverseDepth;
    }
    if (nearest >= 0) draw(x, y, nearest, counters);
  }

  void draw(int x, int y, int polygon, SubdivisionCounters& counters) const {
    ++counters.pixelsWritten;
    frame_.setVisible(x, y, screen_.polygons[polygon].face);
  }

  void chargeToPixels(const PixelRect& window, float work) const {
    const float share =
        work / static_cast<float>((window.x1 - window.x0) * (window.y1 - window.y0));
    for (int y = window.y0; y < window.y1; ++y)
      for (int x = window.x0; x < window.x1; ++x) frame_.addCost(x, y, share);
  }

  static std::vector<PixelRect> quadrants(const PixelRect& window) {
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
};

}  // namespace

void AreaSubdivisionRenderer::resolveVisibility(const ScreenGeometry& screen,
                                                const RenderSettings& settings,
                                                RenderObserver& observer, RasterFrame& frame,
                                                Stats& stats) const {
  const Subdivision subdivision(screen, frame);
  std::vector<int> all(screen.polygons.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);

  // The top levels here; the windows below them on threads.
  SubdivisionCounters top;
  std::vector<PendingWindow> pending;
  subdivision.subdivide({0, 0, frame.width(), frame.height()}, all, 0, kParallelLevel, pending,
                        top);
  std::vector<SubdivisionCounters> counters(pending.size());
  std::vector<Tile> tasks;
  for (std::size_t i = 0; i < pending.size(); ++i)
    tasks.push_back({static_cast<int>(i), 0, 0, 0, 0});
  renderTiles(tasks, settings.threads, observer, [&](const Tile& task) {
    std::vector<PendingWindow> none;
    const PendingWindow& window = pending[task.index];
    subdivision.subdivide(window.window, window.candidates, kParallelLevel, -1, none,
                          counters[task.index]);
  });

  SubdivisionCounters total = top;
  for (const SubdivisionCounters& part : counters) total += part;
  stats.add("depth_tests", static_cast<double>(total.depthTests));
  stats.add("pixels_written", static_cast<double>(total.pixelsWritten));
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
