#include "scene/textures/image_texture.hpp"

#include <utility>

#include "scene/textures/texel_sampling.hpp"

namespace rise {

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, TextureFilter filter)
    : image_(std::move(image)), filter_(filter) {
  if (filter == TextureFilter::Trilinear || filter == TextureFilter::EllipticalAverage)
    mipmap_.emplace(*image_);
  if (filter == TextureFilter::SummedArea) sums_.emplace(*image_);
}

Color ImageTexture::colorAt(const SurfacePoint& surface) const { return colorAtUv(surface.uv); }

Color ImageTexture::colorOverFootprint(const SurfacePoint& surface,
                                       const PixelFootprint& footprint) const {
  return colorAtUv(surface.uv, footprint);
}

Color ImageTexture::colorAtUv(const Vec2& uv) const {
  return filter_ == TextureFilter::Nearest ? nearestAt(*image_, uv) : bilinearAt(*image_, uv);
}

Color ImageTexture::colorAtUv(const Vec2& uv, const PixelFootprint& footprint) const {
  switch (filter_) {
    case TextureFilter::Trilinear:
      return mipmap_->trilinearAt(uv, footprint);
    case TextureFilter::EllipticalAverage:
      return mipmap_->ellipticalAverageAt(uv, footprint);
    case TextureFilter::SummedArea:
      return meanOverBoundingRectangle(uv, footprint);
    default:
      return colorAtUv(uv);
  }
}

// The rectangle around the parallelogram the pixel covers, at least a texel
// wide each way: a box filter over the texels, which is bilinear
// interpolation where the footprint is smaller than a texel.
Color ImageTexture::meanOverBoundingRectangle(const Vec2& uv,
                                              const PixelFootprint& footprint) const {
  const Vec2 size(static_cast<float>(image_->width()), static_cast<float>(image_->height()));
  const Vec2 half =
      glm::max(0.5f * (glm::abs(footprint.acrossX) + glm::abs(footprint.downY)) * size, Vec2(0.5f));
  const Vec2 centre = texelCoordinates(*image_, uv);
  return sums_->meanOver(centre - half, centre + half);
}

}  // namespace rise
