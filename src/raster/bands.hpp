// Bands of whole scanlines: how the visible-surface algorithms that sweep the
// image (z-buffer, scanline, and depth sort's painting) share it among
// threads. Each band is drawn with the polygons that reach into it, in the
// algorithm's order, and counts its own work; the counts are summed in band
// order. The bands do not depend on the number of threads, so neither does
// the image.
#pragma once

#include <span>
#include <vector>

#include "core/parallel.hpp"
#include "raster/polygon_coverage.hpp"
#include "raster/screen_geometry.hpp"

namespace rise {

inline constexpr int kBandHeight = 16;

// The image's bands, top to bottom, the full width of the image.
std::vector<PixelRect> makeBands(int width, int height);

// For each band, the polygons of `order` (indices into screen.polygons) whose
// pixel bounds reach into it, in the order given.
std::vector<std::vector<int>> polygonsByBand(const ScreenGeometry& screen,
                                             std::span<const int> order, int height);

// The polygons' indices, 0 to count - 1: the order they were made in.
std::vector<int> inMadeOrder(const ScreenGeometry& screen);

// Calls draw(band, polygons, counters) for every band of a width x height
// image, on the workers, with the polygons of `order` that reach into it and
// counters of its own; returns the counters summed (Counters::operator+=).
template <typename Counters, typename Draw>
Counters drawInBands(const Workers& workers, const ScreenGeometry& screen,
                     std::span<const int> order, int width, int height, const Draw& draw) {
  const std::vector<PixelRect> bands = makeBands(width, height);
  const std::vector<std::vector<int>> polygons = polygonsByBand(screen, order, height);
  return workers.sumOverTasks<Counters>(static_cast<int>(bands.size()), [&](int band,
                                                                            Counters& counters) {
    draw(bands[static_cast<std::size_t>(band)], polygons[static_cast<std::size_t>(band)], counters);
    workers.regionDone(bands[static_cast<std::size_t>(band)]);
  });
}

}  // namespace rise
