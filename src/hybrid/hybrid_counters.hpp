// What the hybrid algorithm (hybrid.cpp) counts, for --stats, rise compare
// and its steps: where each pixel's primary ray came from, which pixels
// spawned rays, and the time of each pass.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "ray/trace_counters.hpp"
#include "render/renderer.hpp"
#include "render/step_recorder.hpp"

namespace rise {

// Where a pixel's primary hit comes from: the item buffer, or a full primary
// ray because the pixel lies outside its item's true outline or inside
// another's.
enum class Verdict : std::uint8_t { FromItemBuffer, Outside, Inside };

// What pass 2 counts, besides the rays: its statistics, in this order.
enum Count {
  kFromItemBuffer,  // primary rays the item buffer answered
  kOutside,         // fallback pixels, by which side of the outline
  kInside,
  kItemTests,
  kSpawning,       // pixels whose shading spawned rays
  kMirrorOrGlass,  // ... reflected or refracted ones among them
  kCountKinds
};

// The counters of a band, a pass or the whole render.
struct HybridCounters {
  TraceCounters traced;  // every intersection test, the full primary rays, the secondary rays
  std::array<std::uint64_t, kCountKinds> counts{};
  double itemBufferSeconds = 0.0;  // pass 1
  double raySeconds = 0.0;         // pass 2

  HybridCounters& operator+=(const HybridCounters& other) {
    traced += other.traced;
    for (int kind = 0; kind < kCountKinds; ++kind) counts[kind] += other.counts[kind];
    itemBufferSeconds += other.itemBufferSeconds;
    raySeconds += other.raySeconds;
    return *this;
  }
};

// Adds the counters to `stats`, the rays' and intersection tests' first.
void addHybridStats(Stats& stats, const HybridCounters& counters);

// What a step of pass 2 shows of a pixel.
struct RayPassPixel {
  Verdict verdict;
  bool mirrorOrGlass;  // its shading spawned reflected or refracted rays
};

// A band of pass 2 as a step: its counters, its pixels settled, those that
// fell back to a full primary ray and those that spawned mirror or glass rays
// marked, as `pixelAt(x, y)` tells of each.
Step raysStep(const PixelRect& band, const HybridCounters& counters,
              const std::function<RayPassPixel(int, int)>& pixelAt);

// The pixels that an outline, followed once every row was shaded, reached
// and made fall back, shaded again: its counters, the pixels marked as in
// raysStep. It settles nothing: their bands did.
Step shadedAgainStep(std::span<const glm::ivec2> pixels, const HybridCounters& counters,
                     const std::function<RayPassPixel(int, int)>& pixelAt);

}  // namespace rise
