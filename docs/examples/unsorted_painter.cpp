// Painting in the order given: the painter's algorithm without its sort, so
// that whichever polygon was made last covers the others, nearest or not.
#include "unsorted_painter.hpp"

#include <cstdint>

#include "raster/bands.hpp"
#include "raster/polygon_coverage.hpp"

namespace rise {

const AlgorithmDescription& UnsortedPainter::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "unsorted-painter", "Paints every polygon in the order it was made", "none");
  return description;
}

void UnsortedPainter::resolveVisibility(const ScreenGeometry& screen, const RenderSettings&,
                                        const Workers& workers, RasterFrame& frame,
                                        Stats& stats) const {
  const auto painted = drawInBands<std::uint64_t>(
      workers, screen, inMadeOrder(screen), frame.width(), frame.height(),
      [&](const PixelRect& band, std::span<const int> polygons, std::uint64_t& pixels) {
        PolygonCoverage coverage;
        for (int polygon : polygons) {
          coverage.reset(screen.cornersOf(screen.polygons[polygon]));
          coverage.forEachPixel(band, [&](int x, int y) {
            frame.setVisible(x, y, screen.polygons[polygon].face);
            ++pixels;
          });
        }
      });
  stats.add("pixels_written", static_cast<double>(painted));
}

}  // namespace rise
