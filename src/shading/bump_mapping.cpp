#include "shading/bump_mapping.hpp"

namespace rise {

Vec3 bumped(const BumpMap& bump, const SurfacePoint& surface) {
  const float area = glm::length(glm::cross(surface.dpdu, surface.dpdv));
  if (area == 0.0f) return surface.shadingNormal;
  const Vec2 du(bump.step().x, 0.0f), dv(0.0f, bump.step().y);
  const float slopeU =
      (bump.heightAt(surface, surface.uv + du) - bump.heightAt(surface, surface.uv - du)) /
      (2.0f * bump.step().x);
  const float slopeV =
      (bump.heightAt(surface, surface.uv + dv) - bump.heightAt(surface, surface.uv - dv)) /
      (2.0f * bump.step().y);
  const Vec3& normal = surface.shadingNormal;
  const Vec3 tilt =
      slopeU * glm::cross(normal, surface.dpdv) + slopeV * glm::cross(surface.dpdu, normal);
  return glm::normalize(normal + tilt / area);
}

Vec3 normalMapped(const NormalMap& map, const SurfacePoint& surface) {
  const Vec3& normal = surface.shadingNormal;
  const Vec3 alongU = surface.dpdu - glm::dot(surface.dpdu, normal) * normal;
  if (glm::dot(alongU, alongU) == 0.0f) return normal;
  const Vec3 tangent = glm::normalize(alongU);
  // v's direction, on the side dP/dv points to: a mirrored mapping flips it.
  Vec3 bitangent = glm::cross(normal, tangent);
  if (glm::dot(bitangent, surface.dpdv) < 0.0f) bitangent = -bitangent;
  const Vec3 local = 2.0f * map.colorAt(surface) - Vec3(1.0f);
  const Vec3 tilted = local.x * tangent + local.y * bitangent + local.z * normal;
  return glm::dot(tilted, tilted) > 0.0f ? glm::normalize(tilted) : normal;
}

}  // namespace rise
