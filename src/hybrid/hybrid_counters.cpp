#include "hybrid/hybrid_counters.hpp"

#include <string>

#include "core/text.hpp"

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

namespace {

// A step of pass 2 with its counters, its pixels marked as `pixelAt` tells
// of each pixel `visit` passes it.
template <typename ForEachPixel>
Step passTwoStep(std::string title, const HybridCounters& counters,
                 const std::function<RayPassPixel(int, int)>& pixelAt,
                 const ForEachPixel& forEachPixel) {
  const auto count = [&](Count kind) { return static_cast<double>(counters.counts[kind]); };
  Step step("rays", std::move(title) + ": " + counted(counters.traced.rays(), "ray") + ", " +
                        counted(counters.traced.intersections.tests, "intersection test"));
  step.values = {{"primary_rays_from_item_buffer", count(kFromItemBuffer)},
                 {"fallback_pixels", count(kOutside) + count(kInside)},
                 {"pixels_spawning_rays", count(kSpawning)},
                 {"pixels_spawning_reflection_or_refraction", count(kMirrorOrGlass)},
                 {"intersection_tests", static_cast<double>(counters.traced.intersections.tests)}};
  StepTable fallbacks{"pixels that fell back", {"x", "y", "side of the outline"}, {}};
  forEachPixel([&](int x, int y) {
    const RayPassPixel pixel = pixelAt(x, y);
    const Vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    if (pixel.mirrorOrGlass) step.shapes.push_back({StepShape::Kind::Point, "rays", {centre}});
    if (pixel.verdict == Verdict::FromItemBuffer) return;
    step.shapes.push_back({StepShape::Kind::Point, "fallback", {centre}});
    fallbacks.rows.push_back({static_cast<double>(x), static_cast<double>(y),
                              pixel.verdict == Verdict::Outside ? "outside" : "inside"});
  });
  step.tables.push_back(std::move(fallbacks));
  return step;
}

}  // namespace

Step raysStep(const PixelRect& band, const HybridCounters& counters,
              const std::function<RayPassPixel(int, int)>& pixelAt) {
  Step step = passTwoStep(
      "rows " + std::to_string(band.y0) + " to " + std::to_string(band.y1 - 1) + " shaded by rays",
      counters, pixelAt, [&](const auto& visit) {
        for (int y = band.y0; y < band.y1; ++y)
          for (int x = band.x0; x < band.x1; ++x) visit(x, y);
      });
  step.settled.push_back(band);
  return step;
}

Step shadedAgainStep(std::span<const glm::ivec2> pixels, const HybridCounters& counters,
                     const std::function<RayPassPixel(int, int)>& pixelAt) {
  return passTwoStep(std::to_string(pixels.size()) +
                         " pixels an outline reached after their rows, shaded again by full "
                         "primary rays",
                     counters, pixelAt, [&](const auto& visit) {
                       for (const glm::ivec2& pixel : pixels) visit(pixel.x, pixel.y);
                     });
}

}  // namespace rise
