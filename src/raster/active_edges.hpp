// The scanline algorithm's edge table and active edge list (Watkins 1970,
// Bouknight 1970, in the form of Dreux 1988), over one band of scanlines:
//  - the edge table: every polygon edge, bucket-sorted by the first scanline
//    whose centre it crosses (Achar_Min_Max, Init_Bucket_Sort);
//  - the active edge list: the edges crossing the current scanline, with
//    where they cross it. Going down a scanline, each edge's crossing moves
//    by its constant step dx/dy (an incremental update), the edges that end
//    leave the list and the table's bucket for the scanline joins it
//    (Remover_Arestas, Inserir_Arestas);
//  - spans: the list is kept in polygon order, so each active polygon's
//    edges lie side by side, and its span on the scanline runs from the
//    leftmost to the rightmost of them (Limites_da_Face). The pixel centres
//    of a span are those from its left end, included, to its right end, left
//    out (the top-left rule).
// The two edges of a shared border start from the same end and take the same
// steps, so their crossings agree exactly and no pixel between two polygons
// is covered twice or missed. The scanline algorithm sweeps the scene's
// polygons so; Crow's shadow volumes sweep their faces so too
// (raster/shadow_volumes.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "raster/pixel_centres.hpp"
#include "raster/screen_geometry.hpp"

namespace rise {

// An edge of a polygon, where it crosses the current scanline's centre.
struct ActiveEdge {
  float x;
  float step;        // how far x moves from one scanline to the next: dx / dy
  int endScanline;   // the first scanline it no longer crosses
  int polygonOrder;  // the polygon's place in the band's list
};

struct EdgeListCounters {
  std::uint64_t edges = 0;             // entries of the edge tables
  std::uint64_t activeEdgeVisits = 0;  // active edges, summed over the scanlines
  std::uint64_t activeEdgesMax = 0;

  EdgeListCounters& operator+=(const EdgeListCounters& other) {
    edges += other.edges;
    activeEdgeVisits += other.activeEdgeVisits;
    activeEdgesMax = std::max(activeEdgesMax, other.activeEdgesMax);
    return *this;
  }
};

class ActiveEdgeList {
 public:
  // The edges of `polygons` (indices into screen.polygons) within `band`.
  ActiveEdgeList(const ScreenGeometry& screen, const PixelRect& band, std::span<const int> polygons,
                 EdgeListCounters& counters);

  // From the previous scanline's list to scanline y's (the band's first, or
  // the one after the last).
  void advanceTo(int y);

  const std::vector<ActiveEdge>& entering(int y) const { return edgeTable_[y - band_.y0]; }
  const std::vector<ActiveEdge>& active() const { return activeEdges_; }
  // The polygon (into screen.polygons) of the band's list at `order`.
  int polygonAt(int order) const { return polygons_[order]; }

  // Calls span(order, left, right) for each active polygon.
  template <typename Span>
  void forEachSpan(const Span& span) const {
    for (std::size_t first = 0; first < activeEdges_.size();) {
      const int order = activeEdges_[first].polygonOrder;
      float left = kInfinity, right = -kInfinity;
      std::size_t next = first;
      for (; next < activeEdges_.size() && activeEdges_[next].polygonOrder == order; ++next) {
        left = std::min(left, activeEdges_[next].x);
        right = std::max(right, activeEdges_[next].x);
      }
      span(order, left, right);
      first = next;
    }
  }

 private:
  void buildEdgeTable(const ScreenGeometry& screen);

  PixelRect band_;
  std::span<const int> polygons_;
  EdgeListCounters& counters_;
  std::vector<std::vector<ActiveEdge>> edgeTable_;  // a bucket per scanline of the band
  std::vector<ActiveEdge> activeEdges_, merged_;
};

// The pixel columns whose centres x + 1/2 lie in [left, right), within
// [0, width): first and end.
inline std::pair<int, int> centresOfSpan(float left, float right, int width) {
  return {std::max(firstCentreFrom(left), 0), std::min(firstCentreFrom(right), width)};
}

}  // namespace rise
