// Transparency for the visible-surface algorithms that can order what they
// draw: a transparent surface (a material with transmission t) is drawn over
// what lies behind it, its own light added to what is behind filtered by t
// times its colour C, as Whitted's ray tracer weighs a refracted ray, here
// going straight through (Kay and Greenberg's transparency without its
// thickness: D. S. Kay and D. Greenberg, "Transparency for computer
// synthesized images", SIGGRAPH 1979). The order matters, so the blending is
// back to front: depth sort paints in that order already (Newell, Newell and
// Sancha name it a virtue of their method); the z-buffer draws the opaque
// polygons first, then the transparent ones sorted by their farthest point.
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
