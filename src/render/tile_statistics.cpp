#include "render/tile_statistics.hpp"

#include <string>
#include <string_view>

namespace rise {
namespace {

constexpr std::string_view kPerRay = "_per_ray";

bool endsWith(const std::string& text, std::string_view end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

Stats combinedTileStats(const AlgorithmDescription& algorithm, const std::vector<Stats>& tiles,
                        double seconds) {
  Stats totals;
  if (algorithm.tileStatistics == TileStatistics::Summed)
    for (const Stats& tile : tiles) totals.accumulate(tile);
  else if (!tiles.empty())
    totals = tiles.front();
  Stats combined;
  for (const auto& [name, value] : totals.entries()) {
    if (name == "render_seconds")
      combined.add(name, seconds);
    else if (name == "rays_per_second")
      combined.add(name, perEach(totals.value("rays"), seconds));
    else if (endsWith(name, kPerRay))
      combined.add(name, perEach(totals.value(name.substr(0, name.size() - kPerRay.size())),
                                 totals.value("rays")));
    else if (name == "samples_per_pixel")  // a setting, the same in every tile
      combined.add(name, tiles.front().value(name));
    else
      combined.add(name, value);
  }
  return combined;
}

}  // namespace rise
