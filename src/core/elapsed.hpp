// Wall-clock time of the parts of a render, for its statistics.
#pragma once

#include <chrono>

namespace rise {

// The seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The seconds work() takes.
template <typename Work>
double secondsOf(const Work& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return secondsSince(start);
}

}  // namespace rise
