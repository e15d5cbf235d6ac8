#include "scene/textures/transformed_texture.hpp"

#include <cmath>

namespace rise {

Vec2 UvTransform::applyToChange(const Vec2& change) const {
  const float angle = radians(rotateDegrees);
  const float cosine = std::cos(angle), sine = std::sin(angle);
  const Vec2 scaled = scale * change;
  return {cosine * scaled.x - sine * scaled.y, sine * scaled.x + cosine * scaled.y};
}

Vec2 UvTransform::apply(const Vec2& uv) const { return applyToChange(uv) + offset; }

bool UvTransform::isIdentity() const {
  return scale == Vec2(1.0f) && rotateDegrees == 0.0f && offset == Vec2(0.0f);
}

SurfacePoint TransformedTexture::moved(const SurfacePoint& surface) const {
  SurfacePoint result = surface;
  result.uv = transform_.apply(surface.uv);
  return result;
}

Color TransformedTexture::colorAt(const SurfacePoint& surface) const {
  return texture_->colorAt(moved(surface));
}

Color TransformedTexture::colorOverFootprint(const SurfacePoint& surface,
                                             const PixelFootprint& footprint) const {
  return texture_->colorOverFootprint(moved(surface), {transform_.applyToChange(footprint.acrossX),
                                                       transform_.applyToChange(footprint.downY)});
}

}  // namespace rise
