// The statistics of an image rendered in tiles (rise-mpi's ranks, or `rise
// render --tile` commands), as those of the image rendered whole: what the
// tiles count is summed, or any one tile's counters are the image's, as the
// algorithm's description says (TileStatistics). The time is the whole
// run's, and what is counted per ray or per second is worked out again from
// the totals.
#pragma once

#include <vector>

#include "core/stats.hpp"
#include "render/renderer.hpp"

namespace rise {

// `tiles` in the order of the tiles, `seconds` the run's wall-clock time.
Stats combinedTileStats(const AlgorithmDescription& algorithm, const std::vector<Stats>& tiles,
                        double seconds);

}  // namespace rise
