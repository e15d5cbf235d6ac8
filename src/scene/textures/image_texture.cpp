#include "scene/textures/image_texture.hpp"

#include <algorithm>
#include <cmath>

namespace rise {

namespace {

long long wrapped(long long index, int size) {
  const long long remainder = index % size;
  return remainder < 0 ? remainder + size : remainder;
}

// The texel at column x, row y, repeating the image in both directions.
const Color& texel(const Image& image, long long x, long long y) {
  return image.at(static_cast<int>(wrapped(x, image.width())),
                  static_cast<int>(wrapped(y, image.height())));
}

Color nearestAt(const Image& image, const Vec2& uv) {
  // Rows run down, v up.
  const float x = uv.x * static_cast<float>(image.width());
  const float y = (1.0f - uv.y) * static_cast<float>(image.height());
  return texel(image, static_cast<long long>(std::floor(x)), static_cast<long long>(std::floor(y)));
}

Color bilinearAt(const Image& image, const Vec2& uv) {
  // Texel centres are at half-integer image coordinates.
  const float x = uv.x * static_cast<float>(image.width()) - 0.5f;
  const float y = (1.0f - uv.y) * static_cast<float>(image.height()) - 0.5f;
  const float left = std::floor(x), top = std::floor(y);
  const float across = x - left, down = y - top;
  const auto column = static_cast<long long>(left);
  const auto row = static_cast<long long>(top);
  const Color upper = glm::mix(texel(image, column, row), texel(image, column + 1, row), across);
  const Color lower =
      glm::mix(texel(image, column, row + 1), texel(image, column + 1, row + 1), across);
  return glm::mix(upper, lower, down);
}

// Half the size (rounded up), each texel the mean of the 2 x 2 it covers;
// the image repeats, so an odd edge averages with the other side.
Image halved(const Image& image) {
  Image half(std::max(1, (image.width() + 1) / 2), std::max(1, (image.height() + 1) / 2));
  for (int y = 0; y < half.height(); ++y)
    for (int x = 0; x < half.width(); ++x)
      half.at(x, y) = 0.25f * (texel(image, 2 * x, 2 * y) + texel(image, 2 * x + 1, 2 * y) +
                               texel(image, 2 * x, 2 * y + 1) + texel(image, 2 * x + 1, 2 * y + 1));
  return half;
}

}  // namespace

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, TextureFilter filter)
    : levels_{*image}, filter_(filter) {
  if (filter != TextureFilter::Trilinear) return;
  while (levels_.back().width() > 1 || levels_.back().height() > 1)
    levels_.push_back(halved(levels_.back()));
}

Color ImageTexture::colorAt(const SurfacePoint& surface) const { return colorAtUv(surface.uv); }

Color ImageTexture::colorOverFootprint(const SurfacePoint& surface,
                                       const PixelFootprint& footprint) const {
  return colorAtUv(surface.uv, footprint);
}

Color ImageTexture::colorAtUv(const Vec2& uv) const {
  return filter_ == TextureFilter::Nearest ? nearestAt(levels_[0], uv) : bilinearAt(levels_[0], uv);
}

Color ImageTexture::colorAtUv(const Vec2& uv, const PixelFootprint& footprint) const {
  if (filter_ != TextureFilter::Trilinear) return colorAtUv(uv);
  // The level whose texels are as wide as the footprint's longer side, in
  // texels of level 0; each level has half as many.
  const Vec2 size(static_cast<float>(levels_[0].width()), static_cast<float>(levels_[0].height()));
  const float texels =
      std::max(glm::length(footprint.acrossX * size), glm::length(footprint.downY * size));
  const float top = static_cast<float>(levels_.size() - 1);
  const float level = texels > 1.0f ? std::min(std::log2(texels), top) : 0.0f;
  const auto finer = static_cast<std::size_t>(std::floor(level));
  const std::size_t coarser = std::min(finer + 1, levels_.size() - 1);
  return glm::mix(bilinearAt(levels_[finer], uv), bilinearAt(levels_[coarser], uv),
                  level - static_cast<float>(finer));
}

}  // namespace rise
