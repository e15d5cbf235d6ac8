#include "ray/shading_frame.hpp"

#include "shading/material_at_point.hpp"

namespace rise {
namespace {

// Built where it is returned, not copied there: a surface point is large,
// and copying it just after the shape wrote it field by field would wait for
// those writes to reach the cache.
SurfacePoint surfaceSeen(const Ray& ray, const Hit& hit, const Material& material) {
  return material.readsTextureFrame() ? hit.shape->surfaceAt(ray, hit)
                                      : hit.shape->pointAt(ray, hit);
}

}  // namespace

ShadingFrame shadingFrame(const Ray& ray, const Hit& hit, const Material& material) {
  ShadingFrame frame{.surface = surfaceSeen(ray, hit, material)};
  frame.surface.shadingNormal = shadingNormal(material, frame.surface);
  frame.toViewer = -glm::normalize(ray.direction);
  frame.time = ray.time;
  frame.entering = glm::dot(frame.surface.normal, frame.toViewer) > 0.0f;
  frame.normal = frame.entering ? frame.surface.normal : -frame.surface.normal;
  frame.shadingNormal = frame.entering ? frame.surface.shadingNormal : -frame.surface.shadingNormal;
  return frame;
}

Ray spawnRay(const ShadingFrame& frame, const Vec3& direction) {
  const float side = glm::dot(direction, frame.normal) >= 0.0f ? 1.0f : -1.0f;
  return Ray{frame.surface.position + (side * kRayEpsilon) * frame.normal, direction, frame.time};
}

}  // namespace rise
