// A texture read from an image file, laid over the unit square of texture
// coordinates (u to the right, v up, so that the image's top row is at
// v = 1) and repeated beyond it.
#pragma once

#include <memory>
#include <vector>

#include "core/image.hpp"
#include "scene/textures/texture.hpp"

namespace rise {

// How a texture between its texels is sampled: the nearest texel, or the
// four around the point weighted by their nearness (bilinear); trilinear
// also blends between the two levels of a mipmap (L. Williams, "Pyramidal
// Parametrics", SIGGRAPH 1983) whose texels are the size of the pixel's
// footprint, where an algorithm gives one (the visible-surface algorithms),
// and is bilinear otherwise.
enum class TextureFilter { Nearest, Bilinear, Trilinear };

class ImageTexture final : public Texture {
 public:
  ImageTexture(std::shared_ptr<const Image> image, TextureFilter filter);

  Color colorAt(const SurfacePoint& surface) const override;
  Color colorOverFootprint(const SurfacePoint& surface,
                           const PixelFootprint& footprint) const override;
  Color colorAtUv(const Vec2& uv) const;
  // Over a pixel's footprint: trilinear only.
  Color colorAtUv(const Vec2& uv, const PixelFootprint& footprint) const;

  // The mipmap: the image, then each level half the one before (a box
  // filter over 2 x 2 texels), down to a single texel.
  const std::vector<Image>& levels() const { return levels_; }

 private:
  std::vector<Image> levels_;
  TextureFilter filter_;
};

}  // namespace rise
