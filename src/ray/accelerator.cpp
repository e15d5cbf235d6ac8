#include "ray/accelerator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "ray/bounding_spheres.hpp"
#include "ray/brute_force.hpp"
#include "ray/bvh.hpp"
#ifdef RISE_HAS_EMBREE
#include "ray/embree_accelerator.hpp"
#endif

namespace rise {

std::vector<Accel> availableAccels() {
#ifdef RISE_HAS_EMBREE
  return {Accel::None, Accel::Spheres, Accel::Bvh, Accel::Embree};
#else
  return {Accel::None, Accel::Spheres, Accel::Bvh};
#endif
}

bool isAvailable(Accel accel) {
  const std::vector<Accel> available = availableAccels();
  return std::find(available.begin(), available.end(), accel) != available.end();
}

void Accelerator::nearestOfPacket(RayPacket& packet, float tMin) const {
  for (int i = 0; i < packet.size; ++i)
    packet.found[i] = nearest(packet.rays[i], tMin, packet.hits[i], packet.costs[i]);
}

void Accelerator::visitCrossingsOfPacket(
    ShadowRayPacket& packet, float tMin,
    const std::array<CrossingVisitor*, kPacketSize>& visitors) const {
  for (int i = 0; i < packet.size; ++i)
    visitCrossings(packet.rays[i], tMin, packet.tMax[i], *visitors[i], packet.costs[i]);
}

std::unique_ptr<Accelerator> buildAccelerator(Accel accel,
                                              const std::vector<std::unique_ptr<Shape>>& shapes,
                                              int threads) {
  switch (accel) {
    case Accel::None:
      return std::make_unique<BruteForce>(shapes);
    case Accel::Spheres:
      return std::make_unique<BoundingSpheres>(shapes);
    case Accel::Bvh:
      return std::make_unique<Bvh>(shapes, threads);
    case Accel::Embree:
#ifdef RISE_HAS_EMBREE
      return std::make_unique<EmbreeAccelerator>(shapes, threads);
#else
      break;
#endif
  }
  throw std::invalid_argument("this build of RISE has no '" + std::string(accelName(accel)) +
                              "' acceleration structure");
}

}  // namespace rise
