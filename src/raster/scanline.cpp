// The scanline algorithm, after Watkins (1970) and Bouknight (1970), in the
// form of the original RISE report, which follows Dreux (1988): a depth buffer
// and a face buffer only one scanline wide.
//
// The image is built one scanline at a time, top to bottom:
//  - the edge table: every polygon edge, bucket-sorted by the first scanline
//    whose centre it crosses (Achar_Min_Max, Init_Bucket_Sort);
//  - the active edge list: the edges crossing the current scanline, with
//    where they cross it. Going down a scanline, each edge's crossing moves
//    by its constant step dx/dy (an incremental update), the edges that end
//    leave the list and the table's bucket for the scanline joins it
//    (Remover_Arestas, Inserir_Arestas);
//  - spans: the list is kept in polygon order, so each active polygon's
//    edges lie side by side, and its span on the scanline runs from the
//    leftmost to the rightmost of them (Limites_da_Face);
//  - the pixel centres of each span, left edge in and right edge out (the
//    top-left rule), are compared in depth with the scanline's depth buffer,
//    and the nearer polygon's number is kept in the face buffer
//    (Processar_Faces_Ativas); the finished scanline is shaded, and the
//    buffers cleared for the next (gerar_scanline, Atualizar_Buffers).
//
// The memory of the buffers ("scanline_buffer_bytes") grows with the image's
// width only, where the z-buffer's grows with its area. The two edges of a
// shared border start from the same end and take the same steps, so their
// crossings agree exactly and no pixel between two polygons is drawn twice or
// missed. The image is cut into bands of scanlines that threads sweep in
// parallel, each band starting its edges at its first scanline, with buffers
// of its own. Cost of a pixel: the depth tests made at it.
//
// Transparency along the spans, after D. S. Kay and D. Greenberg,
// "Transparency for computer synthesized images", SIGGRAPH 1979: a
// transparent face does not enter the depth and face buffers; each pixel of
// the scanline keeps instead the transparent faces met in front of its
// nearest opaque face so far, with their depths, farthest first. When the
// scanline is finished, those behind the pixel's final opaque face are
// dropped and the rest blended over it, farthest first, by the z-buffer's
// rule (raster/transparency.hpp); "transparent_blends" counts them. The
// memory stays one scanline wide: the buffers, and a depth and a face for
// each transparent face kept at a pixel of the most crowded scanline, which
// "scanline_buffer_bytes" adds.
// The hybrid algorithm's item buffer, whose rays see through glass, keeps
// the nearest face, transparent or not.
#include "raster/scanline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "raster/bands.hpp"
#include "raster/transparency.hpp"

namespace rise {

const AlgorithmDescription& ScanlineRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "scanline",
      "Watkins' and Bouknight's scanline algorithm with Dreux's one-scanline depth "
      "buffer",
      "M. Dreux, A simple effective linear-growth scanline algorithm, ICONCG 1988; G. "
      "S. Watkins, PhD thesis, University of Utah, 1970; W. J. Bouknight, CACM 13(9), "
      "1970; D. S. Kay and D. Greenberg, Transparency for computer synthesized images, "
      "SIGGRAPH 1979",
      {Effect::Transparency});
  return description;
}

namespace {

struct ScanlineCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  std::uint64_t edges = 0;             // entries of the edge tables
  std::uint64_t activeEdgeVisits = 0;  // active edges, summed over the scanlines
  std::uint64_t activeEdgesMax = 0;
  std::uint64_t blends = 0;
  std::uint64_t layersMax = 0;  // transparent faces kept on one scanline, at the most

  ScanlineCounters& operator+=(const ScanlineCounters& other) {
    depthTests += other.depthTests;
    pixelsWritten += other.pixelsWritten;
    edges += other.edges;
    activeEdgeVisits += other.activeEdgeVisits;
    activeEdgesMax = std::max(activeEdgesMax, other.activeEdgesMax);
    blends += other.blends;
    layersMax = std::max(layersMax, other.layersMax);
    return *this;
  }
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
  // `blending`, the frame transparent faces are blended on, or nullptr
  // where every face is drawn as opaque.
  BandSweep(const ScreenGeometry& screen, const PixelRect& band, std::span<const int> polygons,
            VisibleFaces& faces, RasterFrame* blending, ScanlineCounters& counters)
      : screen_(screen),
        band_(band),
        polygons_(polygons),
        faces_(faces),
        blending_(blending),
        counters_(counters),
        edgeTable_(band.y1 - band.y0),
        lineInverseDepth_(faces.width(), 0.0f),
        lineFace_(faces.width(), -1),
        lineCost_(faces.width(), 0.0f),
        lineLayers_(blending ? faces.width() : 0) {}

  void run() {
    buildEdgeTable();
    for (int y = band_.y0; y < band_.y1; ++y) {
      updateActiveEdges(y);
      drawSpans(y);
      if (StepRecorder* steps = faces_.steps()) steps->record(scanlineStep(y), y);
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

  // Calls span(order, left, right) for each active polygon: its edges lie
  // side by side in the list, and its span runs from the leftmost to the
  // rightmost.
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

  void drawSpans(int y) {
    forEachSpan([&](int order, float left, float right) {
      const int face = screen_.polygons[polygons_[order]].face;
      if (blending_ && blending_->isTransparent(face))
        drawTransparentSpan(y, face, left, right);
      else
        drawSpan(y, face, left, right);
    });
  }

  // Calls visit(x, inverseDepth) at the centres x + 1/2 in [left, right).
  template <typename Visit>
  void forEachCentre(int y, int face, float left, float right, const Visit& visit) {
    const ScreenFace& screenFace = screen_.faces[face];
    const int x0 = std::max(firstScanlineFrom(left), 0);
    const int x1 = std::min(firstScanlineFrom(right), faces_.width());
    const float centreY = static_cast<float>(y) + 0.5f;
    for (int x = x0; x < x1; ++x) {
      ++counters_.depthTests;
      ++lineCost_[x];
      // The face's own affine depth, not one stepped along the span, so
      // that every algorithm compares the very same depths.
      visit(x, screenFace.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, centreY)));
    }
  }

  void drawSpan(int y, int face, float left, float right) {
    forEachCentre(y, face, left, right, [&](int x, float inverseDepth) {
      if (inverseDepth <= lineInverseDepth_[x]) return;
      lineInverseDepth_[x] = inverseDepth;
      lineFace_[x] = face;
      ++counters_.pixelsWritten;
    });
  }

  // A transparent face joins the pixels' layers where it is in front of the
  // opaque face so far.
  void drawTransparentSpan(int y, int face, float left, float right) {
    forEachCentre(y, face, left, right, [&](int x, float inverseDepth) {
      if (inverseDepth > lineInverseDepth_[x]) lineLayers_.add(x, inverseDepth, face);
    });
  }

  void emitScanline(int y) {
    counters_.layersMax = std::max<std::uint64_t>(counters_.layersMax, lineLayers_.held());
    for (int x = 0; x < faces_.width(); ++x) {
      if (blending_ && lineLayers_.holdsAny(x)) {
        counters_.blends += lineLayers_.show(*blending_, x, y, lineFace_[x], lineInverseDepth_[x]);
      } else if (lineFace_[x] >= 0) {
        faces_.setVisible(x, y, lineFace_[x]);
      }
      if (lineCost_[x] > 0.0f) faces_.addCost(x, y, lineCost_[x]);
      lineInverseDepth_[x] = 0.0f;
      lineFace_[x] = -1;
      lineCost_[x] = 0.0f;
    }
  }

  // The scanline as a student follows it: the edges entering from the edge
  // table, the active edge list, the spans, and the one-scanline buffers.
  Step scanlineStep(int y) const {
    Step step;
    step.kind = "scanline";
    step.text = "scanline " + std::to_string(y) + ": " +
                std::to_string(edgeTable_[y - band_.y0].size()) + " edges enter, " +
                std::to_string(activeEdges_.size()) + " are active";
    const auto edgeRows = [&](const std::vector<ActiveEdge>& edges) {
      StepTable table{"", {"x", "dx/dy", "end scanline", "polygon"}, {}};
      for (const ActiveEdge& edge : edges)
        table.rows.push_back({edge.x, edge.step, static_cast<double>(edge.endScanline),
                              static_cast<double>(polygons_[edge.polygonOrder])});
      return table;
    };
    step.tables.push_back(edgeRows(edgeTable_[y - band_.y0]));
    step.tables.back().title = "edges entering from the edge table";
    step.tables.push_back(edgeRows(activeEdges_));
    step.tables.back().title = "active edge list";
    for (const ActiveEdge& edge : activeEdges_)
      step.shapes.push_back(
          {StepShape::Kind::Point, "edge", {{edge.x, static_cast<float>(y) + 0.5f}}});
    StepTable spans{"spans", {"polygon", "face", "left", "right"}, {}};
    const float centre = static_cast<float>(y) + 0.5f;
    forEachSpan([&](int order, float left, float right) {
      const int polygon = polygons_[order];
      spans.rows.push_back({static_cast<double>(polygon),
                            static_cast<double>(sceneFaceOf(screen_.polygons[polygon].face)), left,
                            right});
      step.shapes.push_back({StepShape::Kind::Segment, "span", {{left, centre}, {right, centre}}});
    });
    step.tables.push_back(std::move(spans));
    step.tables.push_back(lineBuffers());
    if (StepTable layers = lineLayers(); !layers.rows.empty())
      step.tables.push_back(std::move(layers));
    step.settled.push_back({0, y, faces_.width(), y + 1});
    return step;
  }

  // The scanline's depth and face buffers, as runs of one face.
  StepTable lineBuffers() const {
    StepTable runs{"depth and face buffers", {"from x", "to x", "face", "w at first"}, {}};
    for (int x = 0; x < faces_.width();) {
      int end = x + 1;
      while (end < faces_.width() && lineFace_[end] == lineFace_[x]) ++end;
      const int face = lineFace_[x] < 0 ? -1 : sceneFaceOf(lineFace_[x]);
      runs.rows.push_back({static_cast<double>(x), static_cast<double>(end - 1),
                           static_cast<double>(face), lineInverseDepth_[x]});
      x = end;
    }
    return runs;
  }

  // The transparent faces kept at the scanline's pixels, as runs of pixels
  // with the same: those in front of the opaque face, blended farthest first,
  // and those it turned out to hide.
  StepTable lineLayers() const {
    StepTable runs{"transparent faces over the face buffer",
                   {"from x", "to x", "blended, farthest first", "dropped, behind the face"},
                   {}};
    const auto layersAt = [&](int x) {
      std::string blended, dropped;
      lineLayers_.forEachLayer(x, lineInverseDepth_[x], [&](int face, bool inFront) {
        std::string& list = inFront ? blended : dropped;
        list += (list.empty() ? "" : " ") + std::to_string(sceneFaceOf(face));
      });
      return std::pair(blended, dropped);
    };
    if (!blending_) return runs;
    for (int x = 0; x < faces_.width();) {
      const auto layers = layersAt(x);
      int end = x + 1;
      while (end < faces_.width() && layersAt(end) == layers) ++end;
      if (lineLayers_.holdsAny(x))
        runs.rows.push_back(
            {static_cast<double>(x), static_cast<double>(end - 1), layers.first, layers.second});
      x = end;
    }
    return runs;
  }

  // The number in the scene of screen face `face`, as the "face" buffer has it.
  int sceneFaceOf(int face) const { return screen_.faces[face].sceneFace; }

  const ScreenGeometry& screen_;
  const PixelRect& band_;
  std::span<const int> polygons_;
  VisibleFaces& faces_;
  RasterFrame* blending_;
  ScanlineCounters& counters_;
  std::vector<std::vector<ActiveEdge>> edgeTable_;  // a bucket per scanline of the band
  std::vector<ActiveEdge> activeEdges_, merged_;
  std::vector<float> lineInverseDepth_;  // 0: infinitely far
  std::vector<int> lineFace_;            // -1: none
  std::vector<float> lineCost_;          // the depth tests made at each pixel
  TransparentRow lineLayers_;            // empty unless blending
};

// Sweeps the image, blending transparent faces on `blending` unless it is
// nullptr.
ScanlineCounters sweep(const ScreenGeometry& screen, const Workers& workers, VisibleFaces& faces,
                       RasterFrame* blending, Stats& stats) {
  const ScanlineCounters counters = drawInBands<ScanlineCounters>(
      workers, screen, inMadeOrder(screen), faces.width(), faces.height(),
      [&](const PixelRect& band, std::span<const int> polygons, ScanlineCounters& bandCounters) {
        BandSweep(screen, band, polygons, faces, blending, bandCounters).run();
      });
  stats.add("depth_tests", static_cast<double>(counters.depthTests));
  stats.add("pixels_written", static_cast<double>(counters.pixelsWritten));
  stats.add("edge_table_entries", static_cast<double>(counters.edges));
  stats.add("active_edges_per_scanline",
            static_cast<double>(counters.activeEdgeVisits) / std::max(faces.height(), 1));
  stats.add("active_edges_max", static_cast<double>(counters.activeEdgesMax));
  stats.add("scanline_buffer_bytes",
            static_cast<double>(faces.width()) * (sizeof(float) + sizeof(int)) +
                static_cast<double>(counters.layersMax) * TransparentRow::kBytesALayer);
  return counters;
}

}  // namespace

void ScanlineRenderer::resolveVisibility(const ScreenGeometry& screen,
                                         const RenderSettings& /*settings*/, const Workers& workers,
                                         RasterFrame& frame, Stats& stats) const {
  const ScanlineCounters counters = sweep(screen, workers, frame, &frame, stats);
  stats.add("transparent_blends", static_cast<double>(counters.blends));
}

void sweepScanlines(const ScreenGeometry& screen, const Workers& workers, VisibleFaces& faces,
                    Stats& stats) {
  sweep(screen, workers, faces, nullptr, stats);
}

}  // namespace rise
