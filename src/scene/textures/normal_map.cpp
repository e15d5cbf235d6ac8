#include "scene/textures/normal_map.hpp"

namespace rise {

Vec3 NormalMap::shadingNormalAt(const SurfacePoint& surface) const {
  const Vec3& normal = surface.shadingNormal;
  const Vec3 alongU = surface.dpdu - glm::dot(surface.dpdu, normal) * normal;
  if (glm::dot(alongU, alongU) == 0.0f) return normal;
  const Vec3 tangent = glm::normalize(alongU);
  // v's direction, on the side dP/dv points to: a mirrored mapping flips it.
  Vec3 bitangent = glm::cross(normal, tangent);
  if (glm::dot(bitangent, surface.dpdv) < 0.0f) bitangent = -bitangent;
  const Vec3 local = 2.0f * map_->colorAt(surface) - Vec3(1.0f);
  const Vec3 tilted = local.x * tangent + local.y * bitangent + local.z * normal;
  return glm::dot(tilted, tilted) > 0.0f ? glm::normalize(tilted) : normal;
}

}  // namespace rise
