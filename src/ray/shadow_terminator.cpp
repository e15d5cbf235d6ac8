#include "ray/shadow_terminator.hpp"

#include "scene/shapes/vertex_attributes.hpp"

namespace rise {

Vec3 shadowRayOrigin(const SurfacePoint& surface, const Vec3& sideNormal) {
  if (!surface.interpolation) return surface.position;
  const NormalInterpolation& triangle = *surface.interpolation;
  Vec3 lift(0.0f);
  for (int corner = 0; corner < 3; ++corner) {
    const Vec3& normal = triangle.normals[corner];
    const float above = glm::dot(surface.position - triangle.corners[corner], normal);
    if (above < 0.0f) lift -= triangle.weights[corner] * above * normal;
  }
  // Seen from behind, the curved surface lies on the far side.
  return glm::dot(lift, sideNormal) > 0.0f ? surface.position + lift : surface.position;
}

std::optional<Ray> shadowRay(const SurfacePoint& surface, const Vec3& sideNormal,
                             const Vec3& toLight, float time) {
  Vec3 smooth = sideNormal;
  if (surface.interpolation) {
    const NormalInterpolation& triangle = *surface.interpolation;
    const Vec3 interpolated =
        interpolatedNormal(surface.normal, triangle.normals[0], triangle.normals[1],
                           triangle.normals[2], Vec2(triangle.weights.y, triangle.weights.z));
    smooth = glm::dot(sideNormal, surface.normal) >= 0.0f ? interpolated : -interpolated;
  }
  // One object, made in place and returned as it is: a Ray made apart and
  // copied in would be read back just after being written field by field,
  // which waits for the writes.
  std::optional<Ray> shadow;
  if (glm::dot(smooth, toLight) > 0.0f) {
    shadow.emplace();
    shadow->origin = shadowRayOrigin(surface, sideNormal) + kRayEpsilon * sideNormal;
    shadow->direction = toLight;
    shadow->time = time;
  }
  return shadow;
}

}  // namespace rise
