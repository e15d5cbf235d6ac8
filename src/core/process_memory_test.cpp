#include "core/process_memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rise {
namespace {

bool transparentHugePagesExist() {
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

// The flags /proc/self/smaps gives the mapping that holds `address`
// ("rd wr mr mw me ac hg"), or "" if no mapping holds it.
std::string mappingFlags(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t start = 0;
    std::uintptr_t end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> start >> dash >> end && dash == '-') {
      inside = start <= at && at < end;
      continue;
    }
    const std::string field = "VmFlags:";
    if (inside && line.rfind(field, 0) == 0) return line.substr(field.size()) + " ";
  }
  return "";
}

TEST(ProcessMemory, TheHeapsNextBuffersAskForHugePages) {
#ifdef RISE_SANITIZED_BUILD
  GTEST_SKIP() << "the sanitizers' allocator takes the place of the heap";
#endif
  if (!transparentHugePagesExist()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  setUpProcessMemory();
  const std::vector<char> buffer(8 << 20);
  const std::string flags = mappingFlags(buffer.data() + buffer.size() / 2);
  EXPECT_NE(flags.find(" hg "), std::string::npos) << "flags:" << flags;
}

}  // namespace
}  // namespace rise
