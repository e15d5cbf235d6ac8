#include "core/memory_reuse.hpp"

#include <malloc.h>

#include <climits>

namespace rise {

void keepFreedMemoryForReuse() {
  // Blocks up to glibc's largest threshold (32 MiB) come from the heap
  // rather than mappings of their own, and the heap's top is never trimmed.
  constexpr int kLargestHeapBlock = 32 << 20;
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
}

}  // namespace rise
