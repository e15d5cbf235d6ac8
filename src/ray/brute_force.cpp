#include "ray/brute_force.hpp"

namespace rise {

bool BruteForce::nearest(const Ray& ray, float tMin, Hit& hit,
                         IntersectionCounters& counters) const {
  bool found = false;
  for (const auto& shape : shapes_) found |= shape->intersect(ray, tMin, hit, counters);
  return found;
}

void BruteForce::visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                                IntersectionCounters& counters) const {
  for (std::size_t i = 0; i < shapes_.size(); ++i)
    if (crosses(*shapes_[i], ray, tMin, tMax, counters) && !visitor.crossed(static_cast<int>(i)))
      return;
}

}  // namespace rise
