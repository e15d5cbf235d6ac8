#pragma once

#include "scene/scene.hpp"

namespace rise {

// Answers the two questions a ray tracer asks of a scene: what does this ray
// hit first, and how much light gets through along this segment. It tests
// every shape in turn, as the original RISE did before bounding volumes.
class SceneIntersector {
 public:
  explicit SceneIntersector(const Scene& scene) : scene_(scene) {}

  // The nearest hit with t > tMin, or false when the ray escapes.
  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const;

  // The fraction of light that travels along `ray` from t = tMin to t = tMax:
  // zero if an opaque shape is in the way; each transparent shape on the way
  // filters it once by its transmission times its colour. Shadow rays are not
  // refracted, so glass casts a lighter shadow, not a caustic.
  Color transmittance(const Ray& ray, float tMin, float tMax, IntersectionCounters& counters) const;

 private:
  const Scene& scene_;
};

}  // namespace rise
