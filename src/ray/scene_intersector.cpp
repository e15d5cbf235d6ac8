#include "ray/scene_intersector.hpp"

namespace rise {

bool SceneIntersector::nearest(const Ray& ray, float tMin, Hit& hit,
                               IntersectionCounters& counters) const {
  bool found = false;
  for (const auto& shape : scene_.shapes) found |= shape->intersect(ray, tMin, hit, counters);
  return found;
}

Color SceneIntersector::transmittance(const Ray& ray, float tMin, float tMax,
                                      IntersectionCounters& counters) const {
  Color through(1.0f);
  for (const auto& shape : scene_.shapes) {
    Hit blocker;
    blocker.t = tMax;
    if (!shape->intersect(ray, tMin, blocker, counters)) continue;
    const Material& material = scene_.materialOf(*shape);
    if (!material.isTransparent()) return Color(0.0f);
    through *= material.transmission * material.color;
  }
  return through;
}

}  // namespace rise
