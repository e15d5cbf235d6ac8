#include "scene/textures/texture.hpp"

#include <cmath>

namespace rise {

Color CheckerTexture::colorAt(const SurfacePoint& surface) const {
  const auto square = [this](float coordinate) {
    return static_cast<long long>(std::floor(coordinate / size_));
  };
  const bool even = (square(surface.uv.x) + square(surface.uv.y)) % 2 == 0;
  return even ? even_ : odd_;
}

}  // namespace rise
