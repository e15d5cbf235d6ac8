// `rise compare` shared among MPI ranks: rank 0 hands out the algorithms from
// the queue (work_queue.hpp), each rank renders the ones it is given and
// sends back the image and the statistics, and rank 0 writes the folder
// `rise compare` writes, from the same code, once every algorithm is in.
// Each algorithm's time is its render on its rank.
#pragma once

#include "compare.hpp"

namespace rise::mpi {

// Rank 0's part: returns the run's exit status.
int coordinateComparison(const cli::CompareOptions& options, int ranks);

// Every other rank's part: returns its exit status.
int serveComparison(const cli::CompareOptions& options);

}  // namespace rise::mpi
