// Distributed ray tracing (distributed_ray_tracing.cpp tells it).
#pragma once

#include "render/renderer.hpp"
#include "scene/camera.hpp"

namespace rise {

class DistributedRayTracer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

// The ray through the raster position from the point of a thin lens that
// `lens` picks (ViewFrame::lensPoint), aimed at the point the pinhole ray
// meets on the plane in focus; the pinhole ray itself with no aperture.
// Inline, as ViewFrame::primaryRay is, and one named ray throughout, so that
// the ray is made where its caller keeps it: a copy of a ray just written
// field by field would wait for the writes.
inline Ray thinLensRay(const ViewFrame& view, const Vec2& raster, const Vec2& lens) {
  Ray ray = view.primaryRay(raster.x, raster.y);
  if (view.lensRadius() == 0.0f) return ray;
  const Vec3 inFocus = ray.at(view.focalDistance() / glm::dot(ray.direction, view.forward()));
  const Vec2 onLens = view.lensPoint(lens);
  ray.origin = view.eye() + onLens.x * view.right() + onLens.y * view.up();
  ray.direction = glm::normalize(inFocus - ray.origin);
  return ray;
}

}  // namespace rise
