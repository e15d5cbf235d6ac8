// The scanline algorithm (G. S. Watkins, "A real time visible surface
// algorithm", PhD thesis, University of Utah, 1970; W. J. Bouknight, "A
// procedure for generation of three-dimensional half-toned computer graphics
// presentations", CACM 13(9), 1970), in the form of the original RISE report,
// which follows M. Dreux, "A simple effective linear-growth scanline
// algorithm", ICONCG 1988: a depth buffer and a face buffer only one scanline
// wide.
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
// parallel, each band starting its edges at its first scanline; the buffers
// exist once per band being swept. Cost of a pixel: the depth tests made at
// it.
#pragma once

#include "raster/visible_surface_renderer.hpp"

namespace rise {

class ScanlineRenderer final : public VisibleSurfaceRenderer {
 public:
  std::string_view name() const override { return "scanline"; }
  std::string_view summary() const override {
    return "Watkins' and Bouknight's scanline algorithm with Dreux's one-scanline depth buffer";
  }
  std::string_view citation() const override {
    return "M. Dreux, A simple effective linear-growth scanline algorithm, ICONCG 1988; "
           "G. S. Watkins, PhD thesis, University of Utah, 1970; W. J. Bouknight, CACM 13(9), 1970";
  }

 protected:
  void resolveVisibility(const ScreenGeometry& screen, const RenderSettings& settings,
                         RenderObserver& observer, RasterFrame& frame, Stats& stats) const override;
};

}  // namespace rise
