#pragma once

#include "core/color.hpp"
#include "scene/shape.hpp"

namespace rise {

// A colour that varies over a surface, looked up by the surface's texture
// coordinates.
class Texture {
 public:
  virtual ~Texture() = default;
  virtual Color colorAt(const SurfacePoint& surface) const = 0;
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
