// The statistics of an image rendered in tiles on several ranks, as those of
// the image rendered whole: what a tile counts is summed where a tile renders
// only its own pixels (the ray tracers); the other algorithms draw the whole
// frame for every tile and cut the tile from it, so one tile's counters are
// the frame's. The time is the whole run's, and what is counted per ray or
// per second is worked out again from the totals.
#pragma once

#include <vector>

#include "core/stats.hpp"
#include "render/renderer.hpp"

namespace rise::mpi {

// `tiles` in the order of the tiles, `seconds` the run's wall-clock time.
Stats combinedTileStats(Family family, const std::vector<Stats>& tiles, double seconds);

}  // namespace rise::mpi
