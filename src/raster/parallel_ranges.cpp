#include "raster/parallel_ranges.hpp"

#include "render/tiles.hpp"

namespace rise {

void forEachRange(int count, int rangeSize, int threads,
                  const std::function<void(int range, int begin, int end)>& work) {
  // A row of tiles one item high is a list of ranges.
  RenderObserver unobserved;
  renderTiles(makeTiles(count, 1, rangeSize), threads, unobserved,
              [&](const Tile& tile) { work(tile.index, tile.x0, tile.x1); });
}

int rangeCount(int count, int rangeSize) { return (count + rangeSize - 1) / rangeSize; }

}  // namespace rise
