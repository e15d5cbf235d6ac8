// Work on the items of a long list, such as the faces of a mesh, shared among
// threads by consecutive ranges.
#pragma once

#include <functional>

namespace rise {

// Calls work(range, begin, end) once for each range [begin, end) of
// `rangeSize` consecutive items of [0, count) (the last may be shorter),
// numbered in order from 0, on `threads` threads (0: one per core). The
// ranges do not depend on the number of threads, so results kept per range
// and combined in range order do not either.
void forEachRange(int count, int rangeSize, int threads,
                  const std::function<void(int range, int begin, int end)>& work);

// The number of ranges forEachRange makes.
int rangeCount(int count, int rangeSize);

}  // namespace rise
