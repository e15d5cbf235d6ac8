#pragma once

#include <algorithm>
#include <cassert>

#include "core/color.hpp"
#include "core/left_unfilled.hpp"

namespace rise {

// A rectangle of pixels [x0, x1) x [y0, y1): a tile, a band, a window.
struct PixelRect {
  int x0, y0, x1, y1;

  bool isEmpty() const { return x0 >= x1 || y0 >= y1; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  PixelRect intersection(const PixelRect& other) const {
    return {std::max(x0, other.x0), std::max(y0, other.y0), std::min(x1, other.x1),
            std::min(y1, other.y1)};
  }
};

// An image's pixels, row after row.
using Pixels = UnfilledVector<Color>;

// A width x height grid of linear colours, row 0 at the top.
class Image {
 public:
  Image() = default;
  Image(int width, int height, Color fill = Color(0.0f))
      : width_(width), height_(height), pixels_(pixelCount(width, height), fill) {}

  // An image whose pixels hold no colour until they are written: for one
  // written whole, in parallel, before anything reads it.
  static Image unfilled(int width, int height) {
    Image image;
    image.width_ = width;
    image.height_ = height;
    image.pixels_.resize(pixelCount(width, height));
    return image;
  }

  int width() const { return width_; }
  int height() const { return height_; }

  Color& at(int x, int y) { return pixels_[index(x, y)]; }
  const Color& at(int x, int y) const { return pixels_[index(x, y)]; }

  const Pixels& pixels() const { return pixels_; }

 private:
  static std::size_t pixelCount(int width, int height) {
    return static_cast<std::size_t>(width) * height;
  }

  std::size_t index(int x, int y) const {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return static_cast<std::size_t>(y) * width_ + x;
  }

  int width_ = 0;
  int height_ = 0;
  Pixels pixels_;
};

// The pixels of `image` inside `area`, which lies within it.
inline Image cropped(const Image& image, const PixelRect& area) {
  Image piece(area.width(), area.height());
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x) piece.at(x - area.x0, y - area.y0) = image.at(x, y);
  return piece;
}

}  // namespace rise
