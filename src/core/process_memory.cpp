#include "core/process_memory.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <cstdlib>

namespace rise {

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// glibc's largest threshold for a block to be a mapping of its own.
constexpr int kLargestHeapBlock = 32 << 20;
constexpr int kHeapOnHugePages = 1 << 30;
// glibc's M_TOP_PAD when nobody sets it (DEFAULT_TOP_PAD).
constexpr int kDefaultTopPad = 128 << 10;

void keepFreedMemoryForReuse() {
  // Blocks up to the largest threshold come from the heap rather than
  // mappings of their own, and the heap's top is never trimmed.
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
}

bool addressSpaceIsLimited() {
  rlimit limit{};
  return getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur != RLIM_INFINITY;
}

// The heap grows once by kHeapOnHugePages: a block larger than its top is
// taken with that much padding and given back (and, the heap never being
// trimmed, the padding stays). Then the whole huge pages of what it grew by
// are advised, before anything touches them. Should the heap not grow (no
// room for it, or another allocator than glibc's), nothing is advised.
void growHeapOnHugePages() {
  if (addressSpaceIsLimited()) return;
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  mallopt(M_TOP_PAD, kHeapOnHugePages);
  void* volatile block = std::malloc(kLargestHeapBlock / 2);
  std::free(block);
  mallopt(M_TOP_PAD, kDefaultTopPad);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t first = (before + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = after & ~(kHugePage - 1);
  if (first < last) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

}  // namespace

void setUpProcessMemory() {
  keepFreedMemoryForReuse();
  growHeapOnHugePages();
}

}  // namespace rise
