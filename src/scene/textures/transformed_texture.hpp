// A texture moved over the surface: its texture coordinates are scaled
// (a scale of 2 repeats the texture twice across the unit square), rotated
// counter-clockwise by an angle, then offset, before the texture is looked
// up: uv' = R(angle) (scale * uv) + offset.
#pragma once

#include <memory>

#include "scene/textures/texture.hpp"

namespace rise {

struct UvTransform {
  Vec2 scale{1.0f};
  float rotateDegrees = 0.0f;
  Vec2 offset{0.0f};

  Vec2 apply(const Vec2& uv) const;
  // A change of the coordinates, scaled and rotated but not offset.
  Vec2 applyToChange(const Vec2& change) const;
  bool isIdentity() const;
};

class TransformedTexture final : public Texture {
 public:
  TransformedTexture(std::shared_ptr<const Texture> texture, const UvTransform& transform)
      : texture_(std::move(texture)), transform_(transform) {}

  Color colorAt(const SurfacePoint& surface) const override;
  Color colorOverFootprint(const SurfacePoint& surface,
                           const PixelFootprint& footprint) const override;

 private:
  SurfacePoint moved(const SurfacePoint& surface) const;

  std::shared_ptr<const Texture> texture_;
  UvTransform transform_;
};

}  // namespace rise
