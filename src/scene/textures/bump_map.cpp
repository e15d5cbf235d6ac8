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

Vec3 BumpMap::shadingNormalAt(const SurfacePoint& surface) const {
  const float area = glm::length(glm::cross(surface.dpdu, surface.dpdv));
  if (area == 0.0f) return surface.shadingNormal;
  const Vec2 du(step_.x, 0.0f), dv(0.0f, step_.y);
  const float slopeU =
      (heightAt(surface, surface.uv + du) - heightAt(surface, surface.uv - du)) / (2.0f * step_.x);
  const float slopeV =
      (heightAt(surface, surface.uv + dv) - heightAt(surface, surface.uv - dv)) / (2.0f * step_.y);
  const Vec3& normal = surface.shadingNormal;
  const Vec3 tilt =
      slopeU * glm::cross(normal, surface.dpdv) + slopeV * glm::cross(surface.dpdu, normal);
  return glm::normalize(normal + tilt / area);
}

}  // namespace rise
