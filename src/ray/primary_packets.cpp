#include "ray/primary_packets.hpp"

#include <vector>

#include "ray/ray_tracing.hpp"

namespace rise {
namespace {

// The primary hits of a row of a tile, found a packet at a time.
class RowOfPrimaryHits {
 public:
  // `offsets`: where every pixel of the tile places its samples.
  RowOfPrimaryHits(const TracingContext& context, const PixelRect& area,
                   const std::vector<Vec2>& offsets)
      : context_(context), area_(area), offsets_(offsets) {}

  // Sample i of the pixel traced as tracePrimary traces it, from the hit
  // found with the rest of its row's.
  SampleResult trace(const glm::ivec2& pixel, int i, TraceCounters& counters, RayTree* tree) {
    if (pixel.y != row_) findHits(pixel.y);
    const std::size_t sample = static_cast<std::size_t>(pixel.x - area_.x0) * offsets_.size() +
                               static_cast<std::size_t>(i);
    const RayPacket& packet = packets_[sample / kPacketSize];
    const std::size_t lane = sample % kPacketSize;
    counters.intersections += packet.costs[lane];
    SingleRayChoices single;
    return shadeSearchedPrimary(context_, packet.rays[lane],
                                packet.found[lane] ? &packet.hits[lane] : nullptr, single, counters,
                                tree);
  }

 private:
  void findHits(int y) {
    row_ = y;
    packets_.clear();
    for (int x = area_.x0; x < area_.x1; ++x) {
      for (const Vec2& offset : offsets_) {
        if (packets_.empty() || packets_.back().size == kPacketSize) packets_.emplace_back();
        RayPacket& packet = packets_.back();
        const Vec2 raster = Vec2(glm::ivec2(x, y)) + offset;
        packet.rays[static_cast<std::size_t>(packet.size++)] =
            context_.view.primaryRay(raster.x, raster.y);
      }
    }
    for (RayPacket& packet : packets_) context_.intersector.nearestOfPacket(packet, 0.0f);
  }

  const TracingContext& context_;
  PixelRect area_;
  const std::vector<Vec2>& offsets_;
  int row_ = -1;
  std::vector<RayPacket> packets_;
};

}  // namespace

void traceInPrimaryPackets(const TracingContext& context, TileTrace& tile,
                           const RenderSettings& settings) {
  const PixelSampling& sampling = settings.sampling;
  std::vector<Vec2> offsets;
  RowOfPrimaryHits row(context, tile.area(), offsets);
  tracePixels(
      tile, settings.seed,
      [&](const glm::ivec2&, Rng& rng) -> const std::vector<Vec2>& {
        samplePositions(sampling.pattern, sampling.samples, rng, offsets);
        return offsets;
      },
      [&](const glm::ivec2& pixel, int i, Rng&, TraceCounters& counters, RayTree* tree) {
        return row.trace(pixel, i, counters, tree);
      });
}

}  // namespace rise
