// The scanline algorithm, after Watkins (1970) and Bouknight (1970), in the
// form of the original RISE report, which follows Dreux (1988): a depth buffer
// and a face buffer only one scanline wide.
//
// The image is built one scanline at a time, top to bottom, by the edge
// table, the active edge list and the spans of raster/active_edges.hpp:
//  - the pixel centres of each span, left edge in and right edge out (the
//    top-left rule), are compared in depth with the scanline's depth buffer,
//    and the nearer polygon's number is kept in the face buffer
//    (Processar_Faces_Ativas); the finished scanline is shaded, and the
//    buffers cleared for the next (gerar_scanline, Atualizar_Buffers).
//
// The memory of the buffers ("scanline_buffer_bytes") grows with the image's
// width only, where the z-buffer's grows with its area. The image is cut
// into bands of scanlines that threads sweep in parallel, each band starting
// its edges at its first scanline, with buffers of its own. Cost of a pixel:
// the depth tests made at it.
//
// Shadows, with --shadows volume, after F. C. Crow, "Shadow algorithms for
// computer graphics", SIGGRAPH 1977: the faces of the shadow volumes are swept
// down the scanlines beside the scene's polygons, and at each pixel those in
// front of the depth buffer's surface are counted (raster/shadow_volumes.cpp)
// before the scanline is shaded.
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
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/text.hpp"
#include "raster/active_edges.hpp"
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
      "SIGGRAPH 1979; F. C. Crow, Shadow algorithms for computer graphics, SIGGRAPH 1977",
      {Effect::Transparency}, {}, {ShadowMethod::Volume});
  return description;
}

namespace {

struct ScanlineCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  EdgeListCounters edgeList;
  std::uint64_t blends = 0;
  std::uint64_t layersMax = 0;  // transparent faces kept on one scanline, at the most

  ScanlineCounters& operator+=(const ScanlineCounters& other) {
    depthTests += other.depthTests;
    pixelsWritten += other.pixelsWritten;
    edgeList += other.edgeList;
    blends += other.blends;
    layersMax = std::max(layersMax, other.layersMax);
    return *this;
  }
};

class BandSweep {
 public:
  // `blending`, the frame transparent faces are blended on, or nullptr
  // where every face is drawn as opaque.
  BandSweep(const ScreenGeometry& screen, const PixelRect& band, std::span<const int> polygons,
            VisibleFaces& faces, RasterFrame* blending, ScanlineCounters& counters)
      : screen_(screen),
        band_(band),
        faces_(faces),
        width_(faces.width()),
        keepsCost_(faces.keepsCost()),
        blending_(blending),
        counters_(counters),
        edges_(screen, band, polygons, counters.edgeList),
        lineInverseDepth_(faces.width(), 0.0f),
        lineFace_(faces.width(), -1),
        lineCost_(keepsCost_ ? faces.width() : 0, 0.0f),
        lineLayers_(blending ? faces.width() : 0) {
    if (ShadowVolumes* volumes = blending ? blending->shadowVolumes() : nullptr)
      shadowCount_.emplace(*volumes, band);
  }

  void run() {
    for (int y = band_.y0; y < band_.y1; ++y) {
      edges_.advanceTo(y);
      drawSpans(y);
      if (shadowCount_) shadowCount_->countScanline(y, lineInverseDepth_);
      if (StepRecorder* steps = faces_.steps()) steps->record(scanlineStep(y), y);
      emitScanline(y);
    }
  }

 private:
  void drawSpans(int y) {
    edges_.forEachSpan([&](int order, float left, float right) {
      const int face = screen_.polygons[edges_.polygonAt(order)].face;
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
    const auto [x0, x1] = centresOfSpan(left, right, width_);
    const float centreY = static_cast<float>(y) + 0.5f;
    counters_.depthTests += static_cast<std::uint64_t>(std::max(x1 - x0, 0));
    if (keepsCost_)
      for (int x = x0; x < x1; ++x) ++lineCost_[x];
    for (int x = x0; x < x1; ++x)
      // The face's own affine depth, not one stepped along the span, so
      // that every algorithm compares the very same depths.
      visit(x, screenFace.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, centreY)));
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
    for (int x = 0; x < width_; ++x) {
      if (blending_ && lineLayers_.holdsAny(x)) {
        counters_.blends += lineLayers_.show(*blending_, x, y, lineFace_[x], lineInverseDepth_[x]);
      } else if (lineFace_[x] >= 0) {
        faces_.setVisible(x, y, lineFace_[x]);
      }
      lineInverseDepth_[x] = 0.0f;
      lineFace_[x] = -1;
    }
    if (keepsCost_) emitCost(y);
  }

  void emitCost(int y) {
    for (int x = 0; x < width_; ++x) {
      if (lineCost_[x] > 0.0f) faces_.addCost(x, y, lineCost_[x]);
      lineCost_[x] = 0.0f;
    }
  }

  // The scanline as a student follows it: the edges entering from the edge
  // table, the active edge list, the spans, and the one-scanline buffers.
  Step scanlineStep(int y) const {
    Step step;
    step.kind = "scanline";
    const std::size_t entering = edges_.entering(y).size(), active = edges_.active().size();
    step.text = "scanline " + std::to_string(y) + ": " + counted(entering, "edge") +
                (entering == 1 ? " enters, " : " enter, ") + std::to_string(active) +
                (active == 1 ? " is active" : " are active");
    // A band is swept on its own, from an edge table of its own: every edge
    // that crosses its first scanline enters there, begun above or not.
    if (y == band_.y0 && y > 0)
      step.text += " (the first scanline of the band of rows " + std::to_string(band_.y0) + " to " +
                   std::to_string(band_.y1 - 1) +
                   ", swept on its own: the edges that cross it enter its edge table here, "
                   "wherever they begin)";
    const auto edgeRows = [&](const std::vector<ActiveEdge>& edges) {
      StepTable table{"", {"x", "dx/dy", "end scanline", "polygon"}, {}};
      for (const ActiveEdge& edge : edges)
        table.rows.push_back({edge.x, edge.step, static_cast<double>(edge.endScanline),
                              static_cast<double>(edges_.polygonAt(edge.polygonOrder))});
      return table;
    };
    step.tables.push_back(edgeRows(edges_.entering(y)));
    step.tables.back().title = "edges entering from the edge table";
    step.tables.push_back(edgeRows(edges_.active()));
    step.tables.back().title = "active edge list";
    for (const ActiveEdge& edge : edges_.active())
      step.shapes.push_back(
          {StepShape::Kind::Point, "edge", {{edge.x, static_cast<float>(y) + 0.5f}}});
    StepTable spans{"spans", {"polygon", "face", "left", "right"}, {}};
    const float centre = static_cast<float>(y) + 0.5f;
    edges_.forEachSpan([&](int order, float left, float right) {
      const int polygon = edges_.polygonAt(order);
      spans.rows.push_back({static_cast<double>(polygon),
                            static_cast<double>(sceneFaceOf(screen_.polygons[polygon].face)), left,
                            right});
      step.shapes.push_back({StepShape::Kind::Segment, "span", {{left, centre}, {right, centre}}});
    });
    step.tables.push_back(std::move(spans));
    step.tables.push_back(lineBuffers());
    if (StepTable layers = lineLayers(); !layers.rows.empty())
      step.tables.push_back(std::move(layers));
    if (shadowCount_) step.tables.push_back(shadowCount_->countsTable());
    step.settled.push_back({0, y, width_, y + 1});
    return step;
  }

  // The scanline's depth and face buffers, as runs of one face.
  StepTable lineBuffers() const {
    StepTable runs{"depth and face buffers", {"from x", "to x", "face", "w at first"}, {}};
    for (int x = 0; x < width_;) {
      int end = x + 1;
      while (end < width_ && lineFace_[end] == lineFace_[x]) ++end;
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
        appendListed(list, " ", std::to_string(sceneFaceOf(face)));
      });
      return std::pair(blended, dropped);
    };
    if (!blending_) return runs;
    for (int x = 0; x < width_;) {
      const auto layers = layersAt(x);
      int end = x + 1;
      while (end < width_ && layersAt(end) == layers) ++end;
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
  VisibleFaces& faces_;
  const int width_;       // the faces', asked once rather than at every pixel
  const bool keepsCost_;  // whether lineCost_ is counted, and told
  RasterFrame* blending_;
  ScanlineCounters& counters_;
  ActiveEdgeList edges_;
  std::vector<float> lineInverseDepth_;                  // 0: infinitely far
  std::vector<int> lineFace_;                            // -1: none
  std::vector<float> lineCost_;                          // the depth tests made at each pixel
  TransparentRow lineLayers_;                            // empty unless blending
  std::optional<ShadowVolumes::BandCount> shadowCount_;  // with shadow volumes alone
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
  stats.add("edge_table_entries", static_cast<double>(counters.edgeList.edges));
  stats.add("active_edges_per_scanline",
            static_cast<double>(counters.edgeList.activeEdgeVisits) / std::max(faces.height(), 1));
  stats.add("active_edges_max", static_cast<double>(counters.edgeList.activeEdgesMax));
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
