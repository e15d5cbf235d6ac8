#include "render/tiles.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

namespace rise {

std::vector<Tile> makeTiles(int width, int height, int tileSize) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += tileSize)
    for (int x = 0; x < width; x += tileSize)
      tiles.push_back({static_cast<int>(tiles.size()), x, y, std::min(x + tileSize, width),
                       std::min(y + tileSize, height)});
  return tiles;
}

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void renderTiles(const std::vector<Tile>& tiles, int threads, RenderObserver& observer,
                 const std::function<void(const Tile&)>& renderTile) {
  std::atomic<std::size_t> nextTile{0};
  std::size_t tilesDone = 0;
  std::mutex observerMutex;

  const auto work = [&] {
    for (std::size_t i = nextTile++; i < tiles.size(); i = nextTile++) {
      renderTile(tiles[i]);
      const std::scoped_lock lock(observerMutex);
      observer.onProgress(static_cast<double>(++tilesDone) / static_cast<double>(tiles.size()));
      if (observer.cancelled()) nextTile = tiles.size();
    }
  };

  const int workers = std::min<int>(resolveThreadCount(threads), static_cast<int>(tiles.size()));
  std::vector<std::jthread> pool;
  for (int i = 1; i < workers; ++i) pool.emplace_back(work);
  work();
}

}  // namespace rise
