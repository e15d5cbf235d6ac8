#include "render/tile_statistics.hpp"

#include <algorithm>
#include <string>
#include <string_view>

namespace rise {
namespace {

constexpr std::string_view kPerRay = "_per_ray";

bool endsWith(const std::string& text, std::string_view end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

double largestOf(const std::vector<Stats>& tiles, const std::string& name) {
  double largest = 0.0;
  for (const Stats& tile : tiles) largest = std::max(largest, tile.value(name));
  return largest;
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
    else if (name == "vertices_per_path")
      combined.add(name, perEach(totals.value("path_vertices"), totals.value("paths")));
    else if (name == "samples_per_second")  // a path a sample
      combined.add(name, perEach(totals.value("paths"), seconds));
    else if (name == "passes" || name == "noise")  // the longest tile's, the noisiest tile's
      combined.add(name, largestOf(tiles, name));
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
