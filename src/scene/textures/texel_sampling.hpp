// Reading an image as a texture: texels repeat in both directions, u runs
// to the right and v up (the top row at v = 1), texel centres lie at
// half-integer image coordinates.
#pragma once

#include "core/image.hpp"

namespace rise {

// The image coordinates (x right, y down, in texels) of the point `uv`.
inline Vec2 texelCoordinates(const Image& image, const Vec2& uv) {
  return {uv.x * static_cast<float>(image.width()),
          (1.0f - uv.y) * static_cast<float>(image.height())};
}

// The texel at column x, row y of the image repeated in both directions.
const Color& repeatedTexel(const Image& image, long long x, long long y);

Color nearestAt(const Image& image, const Vec2& uv);
// The four texels around the point, weighted by their nearness.
Color bilinearAt(const Image& image, const Vec2& uv);

}  // namespace rise
