#pragma once

#include "core/color.hpp"
#include "scene/shape.hpp"

namespace rise {

// How far the texture coordinates move from a pixel to the next one across
// and to the one below: the pixel's footprint in the texture, which the
// visible-surface algorithms know from the screen-space derivatives.
struct PixelFootprint {
  Vec2 acrossX{0.0f};
  Vec2 downY{0.0f};
};

// A colour that varies over a surface, looked up by the surface's texture
// coordinates.
class Texture {
 public:
  virtual ~Texture() = default;
  virtual Color colorAt(const SurfacePoint& surface) const = 0;
  // The colour averaged over the pixel's footprint, for the algorithms that
  // know it. A texture that does not filter answers colorAt.
  virtual Color colorOverFootprint(const SurfacePoint& surface,
                                   const PixelFootprint& /*footprint*/) const {
    return colorAt(surface);
  }
};

// Squares of two colours alternating in u and v, `size` units wide: the
// first colour where floor(u / size) + floor(v / size) is even.
class CheckerTexture final : public Texture {
 public:
  CheckerTexture(Color even, Color odd, float size) : even_(even), odd_(odd), size_(size) {}

  Color colorAt(const SurfacePoint& surface) const override;

 private:
  Color even_;
  Color odd_;
  float size_;
};

}  // namespace rise
