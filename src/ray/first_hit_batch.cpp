#include "ray/first_hit_batch.hpp"

#include <array>

namespace rise {

void FirstHitBatch::clear() {
  hits_.clear();
  shadowRays_.clear();
}

// Made where it is kept: a shading's frame is large, and copying one just
// made would wait for its writes.
void FirstHitBatch::add(const Ray& ray, const Hit& hit, PathChoices& choices,
                        TraceCounters& counters) {
  hits_.emplace_back(context_, ray, hit, choices, counters, shadowRays_);
}

void FirstHitBatch::traceShadowRays() {
  visible_.resize(shadowRays_.size());
  shadowCosts_.resize(shadowRays_.size());
  for (int light = 0; light < static_cast<int>(context_.scene.lights.size()); ++light) {
    ShadowRayPacket packet;
    std::array<std::size_t, kPacketSize> rayOfLane{};
    const auto trace = [&] {
      const std::array<Color, kPacketSize> through =
          context_.intersector.transmittanceOfPacket(packet, 0.0f);
      for (std::size_t lane = 0; lane < static_cast<std::size_t>(packet.size); ++lane) {
        visible_[rayOfLane[lane]] = through[lane];
        shadowCosts_[rayOfLane[lane]] = packet.costs[lane];
      }
      packet = ShadowRayPacket{};
    };
    for (std::size_t i = 0; i < shadowRays_.size(); ++i) {
      if (shadowRays_[i].light != light) continue;
      const auto lane = static_cast<std::size_t>(packet.size++);
      rayOfLane[lane] = i;
      packet.rays[lane] = shadowRays_[i].ray;
      packet.tMax[lane] = shadowRays_[i].distance;
      if (packet.size == kPacketSize) trace();
    }
    if (packet.size > 0) trace();
  }
}

bool FirstHitBatch::sentShadowRays(std::size_t i) const {
  return hits_[i].endOfShadowRays() > hits_[i].firstShadowRay();
}

IntersectionCounters FirstHitBatch::shadowRayCosts(std::size_t i) const {
  IntersectionCounters costs;
  for (std::size_t ray = hits_[i].firstShadowRay(); ray < hits_[i].endOfShadowRays(); ++ray)
    costs += shadowCosts_[ray];
  return costs;
}

SampleResult FirstHitBatch::finish(std::size_t i, PathChoices& choices,
                                   TraceCounters& counters) const {
  return hits_[i].finish(context_, choices, counters, shadowRays_, visible_);
}

}  // namespace rise
