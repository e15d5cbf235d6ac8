#include "ray/scene_intersector.hpp"

#include <algorithm>
#include <optional>

#include "core/elapsed.hpp"

namespace rise {
namespace {

// The shapes a shadow ray crosses: the first opaque one ends the search; the
// transparent ones are each kept once, however many of their triangles the
// ray crosses.
class ShadowCrossings final : public CrossingVisitor {
 public:
  // `filters`: empty, its memory reused from ray to ray.
  ShadowCrossings(const Scene& scene, std::vector<int>& filters)
      : scene_(scene), filters_(filters) {}

  bool crossed(int shape) override {
    if (!scene_.materialOf(*scene_.shapes[shape]).isTransparent()) {
      blocked_ = true;
      return false;
    }
    if (std::find(filters_.begin(), filters_.end(), shape) == filters_.end())
      filters_.push_back(shape);
    return true;
  }

  // The filters multiplied in the scene's order, so that every structure,
  // whatever order it found them in, gives the same bits.
  Color transmittance() {
    if (blocked_) return Color(0.0f);
    std::sort(filters_.begin(), filters_.end());
    Color through(1.0f);
    for (int shape : filters_) {
      const Material& material = scene_.materialOf(*scene_.shapes[shape]);
      through *= material.transmission * material.color;
    }
    return through;
  }

 private:
  const Scene& scene_;
  bool blocked_ = false;
  std::vector<int>& filters_;
};

}  // namespace

SceneIntersector::SceneIntersector(const Scene& scene, Accel accel, int threads) : scene_(scene) {
  buildSeconds_ = secondsOf([&] { accelerator_ = buildAccelerator(accel, scene.shapes, threads); });
}

Color SceneIntersector::transmittance(const Ray& ray, float tMin, float tMax,
                                      IntersectionCounters& counters) const {
  // A shadow ray through glass is common; each asking the heap for its list
  // was a hundredth of a render.
  thread_local std::vector<int> filters;
  filters.clear();
  ShadowCrossings crossings(scene_, filters);
  accelerator_->visitCrossings(ray, tMin, tMax, crossings, counters);
  return crossings.transmittance();
}

std::array<Color, kPacketSize> SceneIntersector::transmittanceOfPacket(ShadowRayPacket& packet,
                                                                       float tMin) const {
  thread_local std::array<std::vector<int>, kPacketSize> filters;
  std::array<std::optional<ShadowCrossings>, kPacketSize> crossings;
  std::array<CrossingVisitor*, kPacketSize> visitors{};
  for (int lane = 0; lane < packet.size; ++lane) {
    filters[lane].clear();
    visitors[lane] = &crossings[lane].emplace(scene_, filters[lane]);
  }
  accelerator_->visitCrossingsOfPacket(packet, tMin, visitors);
  std::array<Color, kPacketSize> through{};
  for (int lane = 0; lane < packet.size; ++lane) through[lane] = crossings[lane]->transmittance();
  return through;
}

void SceneIntersector::addBuildStats(Stats& stats) const {
  stats.add("accel_build_seconds", buildSeconds_);
  accelerator_->addStats(stats);
}

}  // namespace rise
