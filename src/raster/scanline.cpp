#include "raster/scanline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/bands.hpp"

namespace rise {
namespace {

struct ScanlineCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  std::uint64_t edges = 0;             // entries of the edge tables
  std::uint64_t activeEdgeVisits = 0;  // active edges, summed over the scanlines
  std::uint64_t activeEdgesMax = 0;
};

// An edge of a polygon, where it crosses the current scanline's centre.
struct ActiveEdge {
  float x;
  float step;        // how far x moves from one scanline to the next: dx / dy
  int endScanline;   // the first scanline it no longer crosses
  int polygonOrder;  // the polygon's place in the band's list
};

// The first scanline whose centre y + 1/2 is at or below `y`.
int firstScanlineFrom(float y) { return static_cast<int>(std::ceil(y - 0.5f)); }

class BandSweep {
 public:
  BandSweep(const ScreenGeometry& screen, const Tile& band, const std::vector<int>& polygons,
            RasterFrame& frame, ScanlineCounters& counters)
      : screen_(screen),
        band_(band),
        polygons_(polygons),
        frame_(frame),
        counters_(counters),
        edgeTable_(band.y1 - band.y0),
        lineInverseDepth_(frame.width(), 0.0f),
        lineFace_(frame.width(), -1) {}

  void run() {
    buildEdgeTable();
    for (int y = band_.y0; y < band_.y1; ++y) {
      updateActiveEdges(y);
      drawSpans(y);
      emitScanline(y);
    }
  }

 private:
  void buildEdgeTable() {
    for (int order = 0; order < static_cast<int>(polygons_.size()); ++order) {
      const std::span<const Vec3> corners = screen_.cornersOf(screen_.polygons[polygons_[order]]);
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vec3& from = corners[i];
        const Vec3& to = corners[(i + 1) % corners.size()];
        if (from.y == to.y) continue;  // horizontal: it crosses no scanline centre
        const Vec3& top = from.y < to.y ? from : to;
        const Vec3& bottom = from.y < to.y ? to : from;
        const int first = std::max(firstScanlineFrom(top.y), band_.y0);
        const int end = std::min(firstScanlineFrom(bottom.y), band_.y1);
        if (first >= end) continue;
        const float step = (bottom.x - top.x) / (bottom.y - top.y);
        const float x = top.x + (static_cast<float>(first) + 0.5f - top.y) * step;
        edgeTable_[first - band_.y0].push_back({x, step, end, order});
        ++counters_.edges;
      }
    }
  }

  // From the previous scanline's list to this one's, kept in polygon order.
  void updateActiveEdges(int y) {
    std::erase_if(activeEdges_, [y](const ActiveEdge& edge) { return edge.endScanline <= y; });
    for (ActiveEdge& edge : activeEdges_) edge.x += edge.step;
    const std::vector<ActiveEdge>& entering = edgeTable_[y - band_.y0];
    merged_.clear();
    std::merge(activeEdges_.begin(), activeEdges_.end(), entering.begin(), entering.end(),
               std::back_inserter(merged_), [](const ActiveEdge& a, const ActiveEdge& b) {
                 return a.polygonOrder < b.polygonOrder;
               });
    activeEdges_.swap(merged_);
    counters_.activeEdgeVisits += activeEdges_.size();
    counters_.activeEdgesMax =
        std::max<std::uint64_t>(counters_.activeEdgesMax, activeEdges_.size());
  }

  void drawSpans(int y) {
    for (std::size_t first = 0; first < activeEdges_.size();) {
      const int order = activeEdges_[first].polygonOrder;
      float left = kInfinity, right = -kInfinity;
      std::size_t next = first;
      for (; next < activeEdges_.size() && activeEdges_[next].polygonOrder == order; ++next) {
        left = std::min(left, activeEdges_[next].x);
        right = std::max(right, activeEdges_[next].x);
      }
      drawSpan(y, screen_.polygons[polygons_[order]].face, left, right);
      first = next;
    }
  }

  // The centres x + 1/2 in [left, right).
  void drawSpan(int y, int face, float left, float right) {
    const ScreenFace& screenFace = screen_.faces[face];
    const int x0 = std::max(firstScanlineFrom(left), 0);
    const int x1 = std::min(firstScanlineFrom(right), frame_.width());
    const float centreY = static_cast<float>(y) + 0.5f;
    for (int x = x0; x < x1; ++x) {
      ++counters_.depthTests;
      frame_.addCost(x, y, 1.0f);
      // The face's own affine depth, not one stepped along the span, so
      // that every algorithm compares the very same depths.
      const float inverseDepth =
          screenFace.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, centreY));
      if (inverseDepth <= lineInverseDepth_[x]) continue;
      lineInverseDepth_[x] = inverseDepth;
      lineFace_[x] = face;
      ++counters_.pixelsWritten;
    }
  }

  void emitScanline(int y) {
    for (int x = 0; x < frame_.width(); ++x) {
      if (lineFace_[x] >= 0) frame_.setVisible(x, y, lineFace_[x]);
      lineInverseDepth_[x] = 0.0f;
      lineFace_[x] = -1;
    }
  }

  const ScreenGeometry& screen_;
  const Tile& band_;
  const std::vector<int>& polygons_;
  RasterFrame& frame_;
  ScanlineCounters& counters_;
  std::vector<std::vector<ActiveEdge>> edgeTable_;  // a bucket per scanline of the band
  std::vector<ActiveEdge> activeEdges_, merged_;
  std::vector<float> lineInverseDepth_;  // 0: infinitely far
  std::vector<int> lineFace_;            // -1: none
};

}  // namespace

void ScanlineRenderer::resolveVisibility(const ScreenGeometry& screen,
                                         const RenderSettings& settings, RenderObserver& observer,
                                         RasterFrame& frame, Stats& stats) const {
  const std::vector<Tile> bands = makeBands(frame.width(), frame.height());
  const std::vector<std::vector<int>> bandPolygons =
      polygonsByBand(screen, inMadeOrder(screen), frame.height());
  std::vector<ScanlineCounters> bandCounters(bands.size());
  renderTiles(bands, settings.threads, observer, [&](const Tile& band) {
    BandSweep(screen, band, bandPolygons[band.index], frame, bandCounters[band.index]).run();
  });

  ScanlineCounters total;
  for (const ScanlineCounters& counters : bandCounters) {
    total.depthTests += counters.depthTests;
    total.pixelsWritten += counters.pixelsWritten;
    total.edges += counters.edges;
    total.activeEdgeVisits += counters.activeEdgeVisits;
    total.activeEdgesMax = std::max(total.activeEdgesMax, counters.activeEdgesMax);
  }
  const int sweptAtOnce =
      std::min(resolveThreadCount(settings.threads), static_cast<int>(bands.size()));
  stats.add("depth_tests", static_cast<double>(total.depthTests));
  stats.add("pixels_written", static_cast<double>(total.pixelsWritten));
  stats.add("edge_table_entries", static_cast<double>(total.edges));
  stats.add("active_edges_per_scanline",
            static_cast<double>(total.activeEdgeVisits) / std::max(frame.height(), 1));
  stats.add("active_edges_max", static_cast<double>(total.activeEdgesMax));
  stats.add("scanline_buffer_bytes",
            static_cast<double>(sweptAtOnce) * frame.width() * (sizeof(float) + sizeof(int)));
}

}  // namespace rise
