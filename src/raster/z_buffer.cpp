// The z-buffer, after Catmull (1974).
//
// Beside the image, a buffer holds the depth of what each pixel shows, all
// pixels starting infinitely far. The polygons are drawn one by one, in any
// order: at each pixel centre a polygon covers (by the top-left fill rule,
// so that a pixel on an edge two polygons share is drawn by one of them),
// its depth is compared with the buffer's, and if nearer it takes the pixel
// and the buffer takes its depth. Nothing is sorted and no two polygons are
// ever compared; the price is memory, a depth and a face for every pixel of
// the image (reported as "z_buffer_bytes"), and the work spent on hidden
// polygons ("overdraw").
//
// Transparent polygons are drawn after the opaque ones, sorted back to front,
// each blended over the pixels where it lies in front of the buffer's depth
// without writing it (raster/transparency.hpp); "transparent_blends" counts
// them.
//
// Depths are compared as w = 1 / n, which is affine across a polygon's image
// and larger for nearer points. The image is cut into bands of scanlines that
// threads draw in parallel, each band with the polygons that reach into it.
// Cost of a pixel: the depth tests made at it.
#include "raster/z_buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "raster/bands.hpp"
#include "raster/polygon_coverage.hpp"
#include "raster/transparency.hpp"

namespace rise {

const AlgorithmDescription& ZBufferRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "z-buffer", "Catmull's z-buffer: a depth per pixel, polygons drawn in any order",
      "E. Catmull, A subdivision algorithm for computer display of curved surfaces, "
      "PhD thesis, University of Utah, 1974",
      {Effect::Transparency});
  return description;
}

namespace {

struct ZBufferCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  std::uint64_t blends = 0;

  ZBufferCounters& operator+=(const ZBufferCounters& other) {
    depthTests += other.depthTests;
    pixelsWritten += other.pixelsWritten;
    blends += other.blends;
    return *this;
  }
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

  void clear(const PixelRect& band) {
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

// The step of drawing one polygon, in the band's part: where it was nearer
// than what the buffer held, and where it was not.
Step polygonDrawn(const ScreenGeometry& screen, int index, const RasterFrame& frame) {
  const ScreenPolygon& polygon = screen.polygons[index];
  Step step;
  step.kind = "polygon";
  step.text = "polygon " + std::to_string(index) + " (face " +
              std::to_string(frame.sceneFaceOf(polygon.face)) +
              "): each pixel it covers takes it if it is nearer than the depth in the buffer";
  step.shapes.push_back(outlineOf(screen.cornersOf(polygon), "polygon"));
  return step;
}

// The transparent polygons, back to front, each blended where it lies in
// front of the opaque surface the buffer holds; `stepOf` numbers their
// steps, after the opaque polygons'.
void blendTransparent(const ScreenGeometry& screen, const PixelRect& band,
                      std::span<const int> polygons, std::span<const std::int64_t> stepOf,
                      const ZBuffer& buffer, RasterFrame& frame, ZBufferCounters& counters) {
  StepRecorder* const steps = frame.steps();
  PolygonCoverage coverage;
  for (int index : transparentBackToFront(screen, frame, polygons)) {
    const ScreenPolygon& polygon = screen.polygons[index];
    const ScreenFace& face = screen.faces[polygon.face];
    std::optional<Step> step;
    if (steps) {
      step = polygonDrawn(screen, index, frame);
      step->text +=
          "; transparent, it is blended over what is behind it, back to front after the "
          "opaque polygons, and leaves the depth buffer as it is";
    }
    coverage.reset(screen.cornersOf(polygon));
    coverage.forEachPixel(band, [&](int x, int y) {
      ++counters.depthTests;
      frame.addCost(x, y, 1.0f);
      const float inverseDepth =
          face.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
      const bool inFront = inverseDepth > buffer.inverseDepth[buffer.index(x, y)];
      if (inFront) {
        frame.blendVisible(x, y, polygon.face);
        ++counters.blends;
      }
      if (!step) return;
      // What the pixel shows is the blend.
      step->writes.push_back(frame.writeOf(x, y, polygon.face, inverseDepth, inFront));
      if (inFront) step->writes.back().color = frame.image().at(x, y);
    });
    if (step) steps->record(std::move(*step), stepOf[index], band.y0);
  }
}

void drawBand(const ScreenGeometry& screen, const PixelRect& band, std::span<const int> polygons,
              std::span<const std::int64_t> blendStepOf, ZBuffer& buffer, RasterFrame& frame,
              ZBufferCounters& counters) {
  buffer.clear(band);
  StepRecorder* const steps = frame.steps();
  PolygonCoverage coverage;
  for (int index : polygons) {
    const ScreenPolygon& polygon = screen.polygons[index];
    const ScreenFace& face = screen.faces[polygon.face];
    if (frame.isTransparent(polygon.face)) continue;
    std::optional<Step> step;
    if (steps) step = polygonDrawn(screen, index, frame);
    coverage.reset(screen.cornersOf(polygon));
    coverage.forEachPixel(band, [&](int x, int y) {
      ++counters.depthTests;
      frame.addCost(x, y, 1.0f);
      const std::size_t pixel = buffer.index(x, y);
      const float inverseDepth =
          face.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
      const bool nearer = inverseDepth > buffer.inverseDepth[pixel];
      if (step) step->writes.push_back(frame.writeOf(x, y, polygon.face, inverseDepth, nearer));
      if (!nearer) return;
      buffer.inverseDepth[pixel] = inverseDepth;
      buffer.face[pixel] = polygon.face;
      ++counters.pixelsWritten;
    });
    if (step) steps->record(std::move(*step), index, band.y0);
  }
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x)
      if (const int face = buffer.face[buffer.index(x, y)]; face >= 0) frame.setVisible(x, y, face);
  blendTransparent(screen, band, polygons, blendStepOf, buffer, frame, counters);
}

}  // namespace

void ZBufferRenderer::resolveVisibility(const ScreenGeometry& screen, const Workers& workers,
                                        RasterFrame& frame, Stats& stats) const {
  ZBuffer buffer(frame.width(), frame.height());
  const std::vector<int> madeOrder = inMadeOrder(screen);
  std::vector<std::int64_t> blendStepOf(madeOrder.size());
  if (frame.steps()) {
    const std::vector<int> blended = transparentBackToFront(screen, frame, madeOrder);
    for (std::size_t i = 0; i < blended.size(); ++i)
      blendStepOf[blended[i]] = static_cast<std::int64_t>(madeOrder.size() + i);
  }
  const ZBufferCounters counters = drawInBands<ZBufferCounters>(
      workers, screen, madeOrder, frame.width(), frame.height(),
      [&](const PixelRect& band, std::span<const int> polygons, ZBufferCounters& bandCounters) {
        drawBand(screen, band, polygons, blendStepOf, buffer, frame, bandCounters);
      });
  stats.add("depth_tests", static_cast<double>(counters.depthTests));
  stats.add("pixels_written", static_cast<double>(counters.pixelsWritten));
  stats.add("transparent_blends", static_cast<double>(counters.blends));
  stats.add("z_buffer_bytes", static_cast<double>(buffer.pixels * (sizeof(float) + sizeof(int))));
}

}  // namespace rise
