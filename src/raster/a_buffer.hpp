// The A-buffer, after Carpenter (1984): L. Carpenter, "The A-buffer, an
// antialiased hidden surface method", SIGGRAPH 1984.
//
// The z-buffer keeps one surface a pixel, so a transparent surface must be
// drawn after everything behind it: the polygons sorted, which no pixel's
// order need agree with. Carpenter's A-buffer keeps at each pixel a list of
// fragments instead, each the depth and the surface of a polygon there, added
// as the polygons come, in any order; when the last polygon is drawn, each
// pixel sorts its own list by depth and composites it. An opaque fragment
// hides what lies behind it, so the fragments behind the nearest opaque one
// leave the list (or never join it), and a pixel covered by opaque surfaces
// alone keeps no list at all, only the z-buffer's depth and face.
//
// Carpenter's fragments also carry a 4 x 8 mask of the part of the pixel a
// polygon covers, so that one pass anti-aliases edges. RISE samples each
// pixel at one point a pass and anti-aliases by the accumulation buffer's
// passes (visible_surface_renderer.hpp), so a fragment covers its pixel or
// not, and the list is what remains of the A-buffer: transparency in any
// order, resolved per pixel.
//
// Its cost is memory that grows with the transparent surfaces' depth at each
// pixel, not with the image alone: the fragments of a band of the image are
// kept until the band is resolved, their most worked out from the
// transparent polygons' bounds before any is taken.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/raster_frame.hpp"

namespace rise {

// What the fragment lists cost: those stored, those cut off behind an opaque
// fragment (on arrival or after), the most resolved at one pixel (the depth
// complexity of the transparent surfaces), and the most memory the lists of
// a band took.
struct ABufferCounters {
  std::uint64_t fragmentsStored = 0;
  std::uint64_t fragmentsCut = 0;
  std::uint64_t mostFragmentsAPixel = 0;
  std::uint64_t mostBytes = 0;

  ABufferCounters& operator+=(const ABufferCounters& other);
};

// The fragment lists of a band of the image: at each pixel, the transparent
// faces in front of the opaque face the z-buffer holds there, in the order
// they came.
class ABuffer {
 public:
  struct Fragment {
    float inverseDepth;  // w = 1 / n, larger for nearer points
    int face;
    int next;  // the next fragment of the pixel's list, -1: none
  };
  static constexpr std::size_t kBytesAFragment = sizeof(Fragment);

  // `mostFragments`: the most the band can come to hold (mostFragmentsByBand).
  ABuffer(const PixelRect& band, std::size_t mostFragments);

  // Transparent face `face` covers pixel (x, y) at inverse depth w, where the
  // nearest opaque face lies at `opaqueDepth`: it joins the pixel's list if
  // it is in front. Returns whether it did.
  bool add(int x, int y, float inverseDepth, int face, float opaqueDepth);
  // An opaque face has taken pixel (x, y) at inverse depth w: the fragments
  // behind it leave the list.
  void cutBehind(int x, int y, float inverseDepth);
  bool holdsAny(int x, int y) const { return first_[index(x, y)] >= 0; }
  // Shows pixel (x, y) on the frame: the opaque face `opaque` (-1: none, the
  // background stays), then the pixel's fragments blended over it, farthest
  // first; returns the blends made.
  std::uint64_t show(RasterFrame& frame, int x, int y, int opaque);

  const ABufferCounters& counters() const { return counters_; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y - band_.y0) * band_.width() + x - band_.x0;
  }

  PixelRect band_;
  std::vector<int> first_;           // each pixel's first fragment, -1: none
  std::vector<Fragment> fragments_;  // every list's fragments, linked by `next`
  int free_ = -1;                    // the fragments cut off, linked for reuse
  std::vector<Fragment> sorted_;     // the pixel show() resolves, by depth
  std::vector<int> faces_;           // its faces, farthest first
  ABufferCounters counters_;
};

// For each band of a height-row image (bands.hpp), the most fragments its
// A-buffer can hold: the pixels in the band of each transparent polygon's
// bounds, as if every one were in front of every opaque one.
std::vector<std::size_t> mostFragmentsByBand(const ScreenGeometry& screen,
                                             const RasterFrame& frame);

}  // namespace rise
