// The memory RISE may take: what a render, a texture or any buffer sized by
// the input is held against before it is allocated, so that no input makes
// RISE fill the machine's memory and die half-way instead of saying why.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rise {

// The memory RISE may take at most, whatever the machine.
inline constexpr std::uint64_t kMostMemory = 64'000'000'000;
// Of the machine's memory, the share RISE may take.
inline constexpr double kShareOfMachineMemory = 0.75;

// The memory RISE may take here, now: the least of kMostMemory, the share of
// the machine's memory, and what the address-space limit of the process
// (ulimit -v) leaves of it. `why` says which it is.
std::uint64_t memoryBudget(std::string* why = nullptr);

// "1.2 GB", "64 GB".
std::string gigabytes(double bytes);

// Why `bytes` of `what` ("decoding the image") cannot be taken, or nothing
// when they fit in the budget: "decoding the image would take about 1.6 GB,
// more than the 0.4 GB RISE may take (what the address-space limit ...)".
std::optional<std::string> memoryProblem(std::uint64_t bytes, const std::string& what);

}  // namespace rise
