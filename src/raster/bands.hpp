// Bands of whole scanlines: how the visible-surface algorithms that sweep the
// image share it among threads. Each band gets the polygons that reach into
// it, in their given order. The bands do not depend on the number of
// threads, so neither does the image.
#pragma once

#include <span>
#include <vector>

#include "raster/screen_geometry.hpp"
#include "render/tiles.hpp"

namespace rise {

inline constexpr int kBandHeight = 16;

// The image's bands, top to bottom, as tiles the full width of the image.
std::vector<Tile> makeBands(int width, int height);

// For each band, the polygons of `order` (indices into screen.polygons) whose
// pixel bounds reach into it, in the order given.
std::vector<std::vector<int>> polygonsByBand(const ScreenGeometry& screen,
                                             std::span<const int> order, int height);

// The polygons' indices, 0 to count - 1: the order they were made in.
std::vector<int> inMadeOrder(const ScreenGeometry& screen);

}  // namespace rise
