#pragma once

#include <array>
#include <memory>

#include "core/stats.hpp"
#include "ray/accelerator.hpp"
#include "scene/scene.hpp"

namespace rise {

// Answers the two questions a ray tracer asks of a scene: what does this ray
// hit first, and how much light gets through along this segment. It builds
// the chosen acceleration structure once, when it is made, and asks it both;
// whichever structure it is, the answers are the same.
class SceneIntersector {
 public:
  // Builds on `threads` threads (0: one per core). Throws
  // std::invalid_argument when this build does not have `accel`.
  SceneIntersector(const Scene& scene, Accel accel, int threads = 0);

  // The nearest hit with t > tMin, or false when the ray escapes.
  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
    return accelerator_->nearest(ray, tMin, hit, counters);
  }

  // The nearest hit of each ray of the packet, as nearest() finds it.
  void nearestOfPacket(RayPacket& packet, float tMin) const {
    accelerator_->nearestOfPacket(packet, tMin);
  }

  // The fraction of light that travels along `ray` from t = tMin to t = tMax:
  // zero if an opaque shape is in the way; each transparent shape on the way
  // filters it once by its transmission times its colour. Shadow rays are not
  // refracted, so glass casts a lighter shadow, not a caustic. The search
  // stops at the first opaque shape found.
  Color transmittance(const Ray& ray, float tMin, float tMax, IntersectionCounters& counters) const;

  // The transmittance of each ray of the packet from tMin to its own end, as
  // transmittance() finds it; each ray's cost in the packet's.
  std::array<Color, kPacketSize> transmittanceOfPacket(ShadowRayPacket& packet, float tMin) const;

  // "accel_build_seconds": how long building the structure took (what the
  // BVH builds at once: it leaves subtrees for the rays to build), and what
  // the structure tells of itself after the render.
  void addBuildStats(Stats& stats) const;

 private:
  const Scene& scene_;
  std::unique_ptr<Accelerator> accelerator_;
  double buildSeconds_ = 0.0;
};

}  // namespace rise
