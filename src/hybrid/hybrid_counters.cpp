#include "hybrid/hybrid_counters.hpp"

namespace rise {
namespace {

constexpr std::array<const char*, kCountKinds> kCountNames = {
    "primary_rays_from_item_buffer",  "fallback_pixels_outside_outline",
    "fallback_pixels_inside_outline", "item_buffer_tests",
    "pixels_spawning_rays",           "pixels_spawning_reflection_or_refraction"};

}  // namespace

void addHybridStats(Stats& stats, const HybridCounters& counters) {
  counters.traced.addTo(stats);
  const auto& counts = counters.counts;
  for (int kind = 0; kind < kCountKinds; ++kind) {
    if (kind == kOutside)
      stats.add("fallback_pixels", static_cast<double>(counts[kOutside] + counts[kInside]));
    stats.add(kCountNames[kind], static_cast<double>(counts[kind]));
  }
  stats.add("item_buffer_seconds", counters.itemBufferSeconds);
  stats.add("ray_pass_seconds", counters.raySeconds);
}

}  // namespace rise
