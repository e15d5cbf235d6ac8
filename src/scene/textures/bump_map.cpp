#include "scene/textures/bump_map.hpp"

namespace rise {

float BumpMap::heightAt(const SurfacePoint& surface, const Vec2& uv) const {
  // Solid textures read the position: it moves with the coordinates.
  SurfacePoint moved = surface;
  moved.uv = uv;
  moved.position += (uv.x - surface.uv.x) * surface.dpdu + (uv.y - surface.uv.y) * surface.dpdv;
  const Color color = height_->colorAt(moved);
  return strength_ * (color.r + color.g + color.b) / 3.0f;
}

}  // namespace rise
