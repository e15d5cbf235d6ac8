#include "raster/bands.hpp"

#include <algorithm>
#include <numeric>

namespace rise {

std::vector<PixelRect> makeBands(int width, int height) {
  std::vector<PixelRect> bands;
  for (int y = 0; y < height; y += kBandHeight)
    bands.push_back({0, y, width, std::min(y + kBandHeight, height)});
  return bands;
}

std::vector<std::vector<int>> polygonsByBand(const ScreenGeometry& screen,
                                             std::span<const int> order, int height) {
  const int bandCount = (height + kBandHeight - 1) / kBandHeight;
  std::vector<std::vector<int>> byBand(bandCount);
  for (int polygon : order) {
    const PixelRect bounds = pixelBoundsOf(screen.cornersOf(screen.polygons[polygon]));
    if (bounds.y1 <= 0 || bounds.y0 >= height) continue;
    const int first = std::max(bounds.y0, 0) / kBandHeight;
    const int last = std::min(bounds.y1 - 1, height - 1) / kBandHeight;
    for (int band = first; band <= last; ++band) byBand[band].push_back(polygon);
  }
  return byBand;
}

std::vector<int> inMadeOrder(const ScreenGeometry& screen) {
  std::vector<int> order(screen.polygons.size());
  std::iota(order.begin(), order.end(), 0);
  return order;
}

}  // namespace rise
