// A texture read from an image file, laid over the unit square of texture
// coordinates (u to the right, v up, so that the image's top row is at
// v = 1) and repeated beyond it.
#pragma once

#include <memory>
#include <optional>

#include "core/image.hpp"
#include "scene/textures/mipmap.hpp"
#include "scene/textures/summed_area_table.hpp"
#include "scene/textures/texture.hpp"

namespace rise {

// How a texture is read between and over its texels: the nearest texel, or
// the four around the point weighted by their nearness (bilinear); or, over
// a pixel's footprint where an algorithm gives one (the visible-surface
// algorithms), the classic answers to minification: a mipmap read
// trilinearly (mipmap.hpp), the mean over the footprint's bounding rectangle
// from a summed-area table (summed_area_table.hpp), or an elliptical weighted
// average over a mipmap (mipmap.hpp). Without a footprint these read
// bilinearly.
enum class TextureFilter { Nearest, Bilinear, Trilinear, SummedArea, EllipticalAverage };

class ImageTexture final : public Texture {
 public:
  ImageTexture(std::shared_ptr<const Image> image, TextureFilter filter);

  Color colorAt(const SurfacePoint& surface) const override;
  Color colorOverFootprint(const SurfacePoint& surface,
                           const PixelFootprint& footprint) const override;
  Color colorAtUv(const Vec2& uv) const;
  Color colorAtUv(const Vec2& uv, const PixelFootprint& footprint) const;

  // The mipmap, for the filters that read one.
  const std::optional<MipMap>& mipmap() const { return mipmap_; }

 private:
  Color meanOverBoundingRectangle(const Vec2& uv, const PixelFootprint& footprint) const;

  std::shared_ptr<const Image> image_;
  TextureFilter filter_;
  std::optional<MipMap> mipmap_;
  std::optional<SummedAreaTable> sums_;
};

}  // namespace rise
