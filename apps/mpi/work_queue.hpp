// The messages of a run shared among MPI ranks. Every rank but 0 says it is
// ready, renders the item it is handed, sends back the result and asks
// again, until it is told to stop; rank 0 hands out the items, in order, to
// whichever rank asks first, so that a slow rank takes fewer. A rank that
// fails says so (after printing why) and the handing out stops: the ranks
// still rendering finish their item and are told to stop.
#pragma once

#include <functional>

#include "render/renderer.hpp"

namespace rise::mpi {

// Rank 0's part: hands out the items 0 to count - 1 and gives each result to
// `take`, which returns an exit status. `status` is rank 0's own (not 0: it
// could not prepare, and hands out nothing). Returns the status of the first
// failure, rank 0's, a rank's or `take`'s, or 0 once every item is taken.
int handOut(int ranks, int count, int status,
            const std::function<int(int item, RenderResult result)>& take);

// Every other rank's part: `prepared` is how preparing went (0: ready), and
// `render` makes an item's result. Returns the rank's exit status.
int serve(int prepared, const std::function<RenderResult(int item)>& render);

}  // namespace rise::mpi
