#pragma once

#include <cstdint>

#include "core/stats.hpp"
#include "scene/shape.hpp"

namespace rise {

// Rays cast by a ray tracer, by kind, and the intersection tests they cost.
struct TraceCounters {
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  std::uint64_t reflectionRays = 0;
  std::uint64_t refractionRays = 0;
  IntersectionCounters intersections;

  std::uint64_t rays() const { return primaryRays + shadowRays + reflectionRays + refractionRays; }

  TraceCounters& operator+=(const TraceCounters& other) {
    primaryRays += other.primaryRays;
    shadowRays += other.shadowRays;
    reflectionRays += other.reflectionRays;
    refractionRays += other.refractionRays;
    intersections += other.intersections;
    return *this;
  }

  void addTo(Stats& stats) const {
    stats.add("rays", static_cast<double>(rays()));
    stats.add("primary_rays", static_cast<double>(primaryRays));
    stats.add("shadow_rays", static_cast<double>(shadowRays));
    stats.add("reflection_rays", static_cast<double>(reflectionRays));
    stats.add("refraction_rays", static_cast<double>(refractionRays));
    stats.add("intersection_tests", static_cast<double>(intersections.tests));
    stats.add("intersection_tests_per_ray",
              perEach(static_cast<double>(intersections.tests), static_cast<double>(rays())));
    stats.add("nodes_visited", static_cast<double>(intersections.nodesVisited));
    stats.add("nodes_visited_per_ray", perEach(static_cast<double>(intersections.nodesVisited),
                                               static_cast<double>(rays())));
  }
};

}  // namespace rise
