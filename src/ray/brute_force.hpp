#pragma once

#include "ray/accelerator.hpp"

namespace rise {

// No acceleration: every ray is tested against every shape, and so against
// every triangle of every mesh, as the original RISE did before bounding
// volumes. The reference the other structures are checked against; its cost
// grows with the scene's size for every ray.
class BruteForce final : public Accelerator {
 public:
  explicit BruteForce(const std::vector<std::unique_ptr<Shape>>& shapes) : shapes_(shapes) {}

  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const override;
  void visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                      IntersectionCounters& counters) const override;

 private:
  const std::vector<std::unique_ptr<Shape>>& shapes_;
};

}  // namespace rise
