#pragma once

#include <functional>
#include <vector>

#include "render/renderer.hpp"

namespace rise {

// A rectangle of pixels [x0, x1) x [y0, y1), the unit of work of a parallel
// render; `index` numbers tiles in row order, so per-tile results can be
// combined in the same order whatever thread rendered them.
struct Tile {
  int index;
  int x0, y0, x1, y1;
};

// Splits a width x height image into square tiles, row by row.
std::vector<Tile> makeTiles(int width, int height, int tileSize = 16);

// The number of threads a render uses: `requested`, or one per hardware
// thread when it is 0.
int resolveThreadCount(int requested);

// Calls renderTile once for every tile, on `threads` threads that each take
// the next tile not yet taken, and reports progress after each tile. Stops
// handing out tiles once the observer asks to cancel. Since every pixel is
// computed from its own coordinates alone, the image does not depend on the
// number of threads or on which thread took which tile.
void renderTiles(const std::vector<Tile>& tiles, int threads, RenderObserver& observer,
                 const std::function<void(const Tile&)>& renderTile);

}  // namespace rise
