#include "core/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace rise {
namespace {

std::uint64_t physicalMemory() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return kMostMemory;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize);
}

// The address space the process already takes, from /proc/self/statm.
std::uint64_t addressSpaceInUse() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGE_SIZE));
}

}  // namespace

std::uint64_t memoryBudget(std::string* why) {
  std::uint64_t budget = kMostMemory;
  std::string reason = "the most RISE may take";
  const auto machine = static_cast<std::uint64_t>(kShareOfMachineMemory * physicalMemory());
  if (machine < budget) {
    budget = machine;
    reason = "3/4 of this machine's " + gigabytes(static_cast<double>(physicalMemory()));
  }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t inUse = addressSpaceInUse();
    const std::uint64_t left = limit.rlim_cur > inUse ? limit.rlim_cur - inUse : 0;
    if (left < budget) {
      budget = left;
      reason = "what the address-space limit (ulimit -v) of " +
               gigabytes(static_cast<double>(limit.rlim_cur)) + " leaves";
    }
  }
  if (why) *why = reason;
  return budget;
}

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, bytes < 10e9 ? "%.1f GB" : "%.0f GB", bytes / 1e9);
  return text;
}

std::optional<std::string> memoryProblem(std::uint64_t bytes, const std::string& what) {
  std::string why;
  const std::uint64_t budget = memoryBudget(&why);
  if (bytes <= budget) return std::nullopt;
  return what + " would take about " + gigabytes(static_cast<double>(bytes)) + ", more than the " +
         gigabytes(static_cast<double>(budget)) + " RISE may take (" + why + ")";
}

}  // namespace rise
