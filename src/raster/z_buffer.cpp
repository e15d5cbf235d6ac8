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
// them. With --transparency a-buffer they are drawn in any order among the
// opaque ones instead, into Carpenter's fragment lists, each pixel's sorted
// by depth at the end (raster/a_buffer.hpp).
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

#include "raster/a_buffer.hpp"
#include "raster/bands.hpp"
#include "raster/polygon_coverage.hpp"
#include "raster/transparency.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& ZBufferRenderer::description() const {
  static const AlgorithmDescription description = visibleSurfaceAlgorithm(
      "z-buffer", "Catmull's z-buffer: a depth per pixel, polygons drawn in any order",
      "E. Catmull, A subdivision algorithm for computer display of curved surfaces, "
      "PhD thesis, University of Utah, 1974",
      {Effect::Transparency}, {Option::Transparency});
  return description;
}

namespace {

struct ZBufferCounters {
  std::uint64_t depthTests = 0;
  std::uint64_t pixelsWritten = 0;
  std::uint64_t blends = 0;
  ABufferCounters fragments;

  ZBufferCounters& operator+=(const ZBufferCounters& other) {
    depthTests += other.depthTests;
    pixelsWritten += other.pixelsWritten;
    blends += other.blends;
    fragments += other.fragments;
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

// What drawing a band works with: the buffer, the frame, the band's
// counters, and the fill rule's edges, taken afresh for each polygon in the
// memory of the last.
struct BandDrawing {
  const PixelRect& band;
  ZBuffer& buffer;
  RasterFrame& frame;
  ZBufferCounters& counters;
  PolygonCoverage coverage{};
};

// Calls test(x, y, w) at each pixel centre of the band that polygon `index`
// covers, with its inverse depth there: a depth test, counted and charged to
// the pixel.
template <typename Test>
void testDepths(const ScreenGeometry& screen, int index, BandDrawing& drawing, const Test& test) {
  const ScreenPolygon& polygon = screen.polygons[index];
  const ScreenFace& face = screen.faces[polygon.face];
  PolygonCoverage& coverage = drawing.coverage;
  RasterFrame& frame = drawing.frame;
  ZBufferCounters& counters = drawing.counters;
  coverage.reset(screen.cornersOf(polygon));
  coverage.forEachPixel(drawing.band, [&](int x, int y) {
    ++counters.depthTests;
    frame.addCost(x, y, 1.0f);
    test(x, y,
         face.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f)));
  });
}

// Draws opaque polygon `index` into the buffer; calls taken(x, y, w) at each
// pixel it takes.
template <typename Taken>
void drawOpaque(const ScreenGeometry& screen, int index, BandDrawing& drawing, const Taken& taken) {
  const int face = screen.polygons[index].face;
  ZBuffer& buffer = drawing.buffer;
  RasterFrame& frame = drawing.frame;
  std::optional<Step> step;
  if (frame.steps()) step = polygonDrawn(screen, index, frame);
  testDepths(screen, index, drawing, [&](int x, int y, float inverseDepth) {
    const std::size_t pixel = buffer.index(x, y);
    const bool nearer = inverseDepth > buffer.inverseDepth[pixel];
    if (step) step->writes.push_back(frame.writeOf(x, y, face, inverseDepth, nearer));
    if (!nearer) return;
    buffer.inverseDepth[pixel] = inverseDepth;
    buffer.face[pixel] = face;
    ++drawing.counters.pixelsWritten;
    taken(x, y, inverseDepth);
  });
  if (step) frame.steps()->record(std::move(*step), index, drawing.band.y0);
}

// The transparent polygons, back to front, each blended where it lies in
// front of the opaque surface the buffer holds; `stepOf` numbers their
// steps, after the opaque polygons'.
void blendTransparent(const ScreenGeometry& screen, std::span<const int> polygons,
                      std::span<const std::int64_t> stepOf, BandDrawing& drawing) {
  RasterFrame& frame = drawing.frame;
  StepRecorder* const steps = frame.steps();
  for (int index : transparentBackToFront(screen, frame, polygons)) {
    const int face = screen.polygons[index].face;
    std::optional<Step> step;
    if (steps) {
      step = polygonDrawn(screen, index, frame);
      step->text +=
          "; transparent, it is blended over what is behind it, back to front after the "
          "opaque polygons, and leaves the depth buffer as it is";
    }
    testDepths(screen, index, drawing, [&](int x, int y, float inverseDepth) {
      const bool inFront = inverseDepth > drawing.buffer.inverseDepth[drawing.buffer.index(x, y)];
      if (inFront) {
        frame.blendVisible(x, y, face);
        ++drawing.counters.blends;
      }
      if (!step) return;
      // What the pixel shows is the blend.
      step->writes.push_back(frame.writeOf(x, y, face, inverseDepth, inFront));
      if (inFront) step->writes.back().color = frame.image().at(x, y);
    });
    if (step) steps->record(std::move(*step), stepOf[index], drawing.band.y0);
  }
}

void showOpaque(const PixelRect& band, const ZBuffer& buffer, RasterFrame& frame) {
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x)
      if (const int face = buffer.face[buffer.index(x, y)]; face >= 0) frame.setVisible(x, y, face);
}

// The opaque polygons first, then the transparent ones sorted back to front.
void drawBandSorted(const ScreenGeometry& screen, std::span<const int> polygons,
                    std::span<const std::int64_t> blendStepOf, BandDrawing& drawing) {
  drawing.buffer.clear(drawing.band);
  for (int index : polygons)
    if (!drawing.frame.isTransparent(screen.polygons[index].face))
      drawOpaque(screen, index, drawing, [](int, int, float) {});
  showOpaque(drawing.band, drawing.buffer, drawing.frame);
  blendTransparent(screen, polygons, blendStepOf, drawing);
}

// Adds transparent polygon `index` to the fragment lists of the pixels where
// it lies in front of the opaque surface the buffer holds so far.
void addFragments(const ScreenGeometry& screen, int index, ABuffer& fragments,
                  BandDrawing& drawing) {
  const int face = screen.polygons[index].face;
  RasterFrame& frame = drawing.frame;
  std::optional<Step> step;
  if (frame.steps()) {
    step = polygonDrawn(screen, index, frame);
    step->text =
        "polygon " + std::to_string(index) + " (face " + std::to_string(frame.sceneFaceOf(face)) +
        "), transparent: it joins the fragment list of each pixel it covers in front of the "
        "opaque surface in the buffer, to be blended by depth when every polygon is drawn";
  }
  testDepths(screen, index, drawing, [&](int x, int y, float inverseDepth) {
    const bool added = fragments.add(x, y, inverseDepth, face,
                                     drawing.buffer.inverseDepth[drawing.buffer.index(x, y)]);
    if (step) step->writes.push_back(frame.writeOf(x, y, face, inverseDepth, added));
  });
  if (step) frame.steps()->record(std::move(*step), index, drawing.band.y0);
}

// Every pixel of the band, its fragments blended over its opaque face by
// depth; the step of it is numbered `order`, after every polygon's.
void resolveFragments(ABuffer& fragments, std::int64_t order, BandDrawing& drawing) {
  const PixelRect& band = drawing.band;
  const ZBuffer& buffer = drawing.buffer;
  RasterFrame& frame = drawing.frame;
  std::optional<Step> step;
  if (frame.steps())
    step.emplace("resolve",
                 "rows " + std::to_string(band.y0) + " to " + std::to_string(band.y1 - 1) +
                     ": each pixel sorts its fragments by depth and blends them, farthest "
                     "first, over its opaque surface");
  for (int y = band.y0; y < band.y1; ++y)
    for (int x = band.x0; x < band.x1; ++x) {
      const int face = buffer.face[buffer.index(x, y)];
      if (!fragments.holdsAny(x, y)) {
        if (face >= 0) frame.setVisible(x, y, face);
        continue;
      }
      drawing.counters.blends += fragments.show(frame, x, y, face);
      if (step)
        step->writes.push_back(
            {x, y, frame.image().at(x, y), face >= 0 ? frame.sceneFaceOf(face) : -1});
    }
  drawing.counters.fragments += fragments.counters();
  if (step && !step->writes.empty()) frame.steps()->record(std::move(*step), order, band.y0);
}

// Carpenter's A-buffer (a_buffer.hpp): every polygon in the order made,
// the transparent ones into fragment lists, which are resolved at the end.
void drawBandWithFragments(const ScreenGeometry& screen, std::span<const int> polygons,
                           std::size_t mostFragments, BandDrawing& drawing) {
  drawing.buffer.clear(drawing.band);
  ABuffer fragments(drawing.band, mostFragments);
  for (int index : polygons) {
    if (drawing.frame.isTransparent(screen.polygons[index].face)) {
      addFragments(screen, index, fragments, drawing);
      continue;
    }
    drawOpaque(screen, index, drawing,
               [&](int x, int y, float inverseDepth) { fragments.cutBehind(x, y, inverseDepth); });
  }
  resolveFragments(fragments, static_cast<std::int64_t>(screen.polygons.size()), drawing);
}

// The most fragments the bands' lists can hold, checked against the memory a
// render may take for as many bands as are drawn at once, before any is
// taken.
std::vector<std::size_t> fragmentsToHold(const ScreenGeometry& screen, const Workers& workers,
                                         const RasterFrame& frame) {
  std::vector<std::size_t> most = mostFragmentsByBand(screen, frame);
  const std::size_t largest = most.empty() ? 0 : *std::max_element(most.begin(), most.end());
  const auto atOnce = static_cast<std::uint64_t>(
      std::min<std::size_t>(static_cast<std::size_t>(workers.threads()), most.size()));
  checkWorkingMemoryFits(atOnce * largest * ABuffer::kBytesAFragment,
                         "the A-buffer's fragment lists, " + std::to_string(largest) +
                             " fragments a band of " + std::to_string(kBandHeight) + " rows on " +
                             std::to_string(atOnce) + " threads,",
                         "--transparency sorted, fewer threads or a smaller image");
  return most;
}

void addFragmentStats(const ABufferCounters& fragments, Stats& stats) {
  stats.add("a_buffer_fragments", static_cast<double>(fragments.fragmentsStored));
  stats.add("a_buffer_fragments_cut", static_cast<double>(fragments.fragmentsCut));
  stats.add("a_buffer_most_fragments", static_cast<double>(fragments.mostFragmentsAPixel));
  stats.add("a_buffer_bytes", static_cast<double>(fragments.mostBytes));
}

}  // namespace

void ZBufferRenderer::resolveVisibility(const ScreenGeometry& screen,
                                        const RenderSettings& settings, const Workers& workers,
                                        RasterFrame& frame, Stats& stats) const {
  ZBuffer buffer(frame.width(), frame.height());
  const std::vector<int> madeOrder = inMadeOrder(screen);
  const bool withFragments = settings.transparency == Transparency::ABuffer;
  const std::vector<std::size_t> mostFragments =
      withFragments ? fragmentsToHold(screen, workers, frame) : std::vector<std::size_t>{};
  std::vector<std::int64_t> blendStepOf(madeOrder.size());
  if (frame.steps() && !withFragments) {
    const std::vector<int> blended = transparentBackToFront(screen, frame, madeOrder);
    for (std::size_t i = 0; i < blended.size(); ++i)
      blendStepOf[blended[i]] = static_cast<std::int64_t>(madeOrder.size() + i);
  }
  const ZBufferCounters counters = drawInBands<ZBufferCounters>(
      workers, screen, madeOrder, frame.width(), frame.height(),
      [&](const PixelRect& band, std::span<const int> polygons, ZBufferCounters& bandCounters) {
        BandDrawing drawing{band, buffer, frame, bandCounters};
        if (withFragments)
          drawBandWithFragments(screen, polygons,
                                mostFragments[static_cast<std::size_t>(band.y0 / kBandHeight)],
                                drawing);
        else
          drawBandSorted(screen, polygons, blendStepOf, drawing);
      });
  stats.add("depth_tests", static_cast<double>(counters.depthTests));
  stats.add("pixels_written", static_cast<double>(counters.pixelsWritten));
  stats.add("transparent_blends", static_cast<double>(counters.blends));
  stats.add("z_buffer_bytes", static_cast<double>(buffer.pixels * (sizeof(float) + sizeof(int))));
  if (withFragments) addFragmentStats(counters.fragments, stats);
}

}  // namespace rise
