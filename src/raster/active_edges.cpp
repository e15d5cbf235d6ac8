#include "raster/active_edges.hpp"

#include <cmath>
#include <iterator>

namespace rise {

ActiveEdgeList::ActiveEdgeList(const ScreenGeometry& screen, const PixelRect& band,
                               std::span<const int> polygons, EdgeListCounters& counters)
    : band_(band), polygons_(polygons), counters_(counters), edgeTable_(band.y1 - band.y0) {
  buildEdgeTable(screen);
}

void ActiveEdgeList::buildEdgeTable(const ScreenGeometry& screen) {
  for (int order = 0; order < static_cast<int>(polygons_.size()); ++order) {
    const std::span<const Vec3> corners = screen.cornersOf(screen.polygons[polygons_[order]]);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Vec3& from = corners[i];
      const Vec3& to = corners[nextCorner(i, corners.size())];
      if (from.y == to.y) continue;  // horizontal: it crosses no scanline centre
      if (hasNoPlace(from) || hasNoPlace(to)) continue;
      const Vec3& top = from.y < to.y ? from : to;
      const Vec3& bottom = from.y < to.y ? to : from;
      const int first = std::max(firstCentreFrom(top.y), band_.y0);
      const int end = std::min(firstCentreFrom(bottom.y), band_.y1);
      if (first >= end) continue;
      const float step = (bottom.x - top.x) / (bottom.y - top.y);
      const float x = top.x + (static_cast<float>(first) + 0.5f - top.y) * step;
      edgeTable_[first - band_.y0].push_back({x, step, end, order});
      ++counters_.edges;
    }
  }
}

// The list stays in polygon order.
void ActiveEdgeList::advanceTo(int y) {
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
  counters_.activeEdgesMax = std::max<std::uint64_t>(counters_.activeEdgesMax, activeEdges_.size());
}

}  // namespace rise
