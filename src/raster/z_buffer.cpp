#include "raster/z_buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "raster/bands.hpp"
#include "raster/polygon_coverage.hpp"

namespace rise {
namespace {

struct ZBufferCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
};

// The depth and face buffers, the size of the image. Each band clears its
// own rows before drawing, on its thread.
struct ZBuffer {
  ZBuffer(int width, int height)
      : width(width),
        pixels(static_cast<std::size_t>(width) * height),
        inverseDepth(new float[pixels]),
        face(new int[pixels]) {}

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }

  void clear(const Tile& band) {
    const std::size_t first = index(band.x0, band.y0);
    const std::size_t end = index(band.x0, band.y1);
    std::fill(inverseDepth.get() + first, inverseDepth.get() + end, 0.0f);
    std::fill(face.get() + first, face.get() + end, -1);
  }

  int width;
  std::size_t pixels;
  std::unique_ptr<float[]> inverseDepth;  // 0: infinitely far
  std::unique_ptr<int[]> face;            // -1: none
};

void drawBand(const ScreenGeometry& screen, const Tile& band, std::span<const int> polygons,
              ZBuffer& buffer, RasterFrame& frame, ZBufferCounters& counters) {
  const PixelRect bandPixels{band.x0, band.y0, band.x1, band.y1};
  buffer.clear(band);
  PolygonCoverage coverage;
  for (int index : polygons) {
    const ScreenPolygon& polygon = screen.polygons[index];
    const ScreenFace& face = screen.faces[polygon.face];
    coverage.reset(screen.cornersOf(polygon));
    coverage.forEachPixel(bandPixels, [&](int x, int y) {
      ++counters.depthTests;
      frame.addCost(x, y, 1.0f);
      const std::size_t pixel = buffer.index(x, y);
      const float inverseDepth =
          face.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
      if (inverseDepth <= buffer.inverseDepth[pixel]) return;
      buffer.inverseDepth[pixel] = inverseDepth;
      buffer.face[pixel] = polygon.face;
      ++counters.pixelsWritten;
    });
  }
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x)
      if (const int face = buffer.face[buffer.index(x, y)]; face >= 0) frame.setVisible(x, y, face);
}

}  // namespace

void ZBufferRenderer::resolveVisibility(const ScreenGeometry& screen,
                                        const RenderSettings& settings, RenderObserver& observer,
                                        RasterFrame& frame, Stats& stats) const {
  ZBuffer buffer(frame.width(), frame.height());
  const std::vector<Tile> bands = makeBands(frame.width(), frame.height());
  const std::vector<std::vector<int>> bandPolygons =
      polygonsByBand(screen, inMadeOrder(screen), frame.height());
  std::vector<ZBufferCounters> bandCounters(bands.size());
  renderTiles(bands, settings.threads, observer, [&](const Tile& band) {
    drawBand(screen, band, bandPolygons[band.index], buffer, frame, bandCounters[band.index]);
  });

  ZBufferCounters total;
  for (const ZBufferCounters& counters : bandCounters) {
    total.depthTests += counters.depthTests;
    total.pixelsWritten += counters.pixelsWritten;
  }
  stats.add("depth_tests", static_cast<double>(total.depthTests));
  stats.add("pixels_written", static_cast<double>(total.pixelsWritten));
  stats.add("z_buffer_bytes", static_cast<double>(buffer.pixels * (sizeof(float) + sizeof(int))));
}

}  // namespace rise
