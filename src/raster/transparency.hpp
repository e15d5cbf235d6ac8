// Transparency for the visible-surface algorithms that can order what they
// draw: a transparent surface (a material with transmission t) is drawn over
// what lies behind it, its own light added to what is behind filtered by t
// times its colour C, as Whitted's ray tracer weighs a refracted ray, here
// going straight through (Kay and Greenberg's transparency without its
// thickness: D. S. Kay and D. Greenberg, "Transparency for computer
// synthesized images", SIGGRAPH 1979). The order matters, so the blending is
// back to front: depth sort paints in that order already (Newell, Newell and
// Sancha name it a virtue of their method); the z-buffer draws the opaque
// polygons first, then the transparent ones sorted by their farthest point;
// the scanline algorithm keeps, at each pixel of its scanline, the nearest
// opaque face and the transparent ones in front of it, by depth.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "raster/raster_frame.hpp"

namespace rise {

// The transparent polygons of `polygons` (indices into screen.polygons),
// farthest first: by their farthest corner, ties by their place in the list.
std::vector<int> transparentBackToFront(const ScreenGeometry& screen, const RasterFrame& frame,
                                        std::span<const int> polygons);

// Shows pixel (x, y) on the frame: the opaque face `opaque` (-1: none, the
// background stays), then the transparent faces `over`, farthest first,
// blended over it; returns the blends made.
std::uint64_t showLayers(RasterFrame& frame, int x, int y, int opaque, std::span<const int> over);

// The transparent faces met at each pixel of a row, each with its inverse
// depth w, kept farthest first as they come (Kay and Greenberg along a
// scanline): what is in front of the pixel's opaque face when the row is
// finished is blended over it.
class TransparentRow {
 public:
  static constexpr std::size_t kBytesALayer = sizeof(float) + sizeof(int);

  explicit TransparentRow(int width) : layers_(static_cast<std::size_t>(width)) {}

  // Transparent face `face` lies at pixel x at inverse depth w: it takes its
  // place among the pixel's layers, after any as far.
  void add(int x, float inverseDepth, int face);
  bool holdsAny(int x) const { return !layers_[static_cast<std::size_t>(x)].empty(); }
  // The layers held on the row.
  std::size_t held() const { return held_; }
  // Calls visit(face, inFront) for pixel x's layers, farthest first, inFront
  // false for those behind the opaque face at inverse depth `opaqueDepth`.
  template <typename Visit>
  void forEachLayer(int x, float opaqueDepth, const Visit& visit) const {
    for (const Layer& layer : layers_[static_cast<std::size_t>(x)])
      visit(layer.face, layer.inverseDepth > opaqueDepth);
  }
  // Shows pixel (x, y) of the row on the frame: the opaque face `opaque`
  // (-1: none) at inverse depth `opaqueDepth`, and the layers in front of it
  // blended over it, farthest first; forgets the pixel's layers and returns
  // the blends made.
  std::uint64_t show(RasterFrame& frame, int x, int y, int opaque, float opaqueDepth);

 private:
  struct Layer {
    float inverseDepth;
    int face;
  };

  std::vector<std::vector<Layer>> layers_;
  std::size_t held_ = 0;
  std::vector<int> inFront_;  // the faces show() blends, reused from pixel to pixel
};

// What painting leaves at each pixel of a band: the last opaque face painted
// there, and the transparent faces painted over it since, in order.
class PaintedLayers {
 public:
  explicit PaintedLayers(const PixelRect& band);

  void paint(int x, int y, int face, bool transparent);
  // The colour the pixel shows as painted so far, for a step's record.
  Color shownAt(const RasterFrame& frame, int x, int y) const;
  // Shows every pixel of the band on the frame, the opaque face first, then
  // the transparent ones blended over it; returns the blends made.
  std::uint64_t show(RasterFrame& frame) const;

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y - band_.y0) * band_.width() + x - band_.x0;
  }

  PixelRect band_;
  std::vector<int> opaque_;             // -1: none
  std::vector<std::vector<int>> over_;  // empty unless transparent faces were painted
};

}  // namespace rise
