#include "core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <thread>

namespace rise {
namespace {

Progress nobody;

}  // namespace

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

Workers::Workers(int threads) : Workers(threads, nobody) {}

Workers::Workers(int threads, Progress& progress)
    : threads_(resolveThreadCount(threads)), progress_(&progress) {}

void Workers::onThreads(int count, const std::function<void(int thread)>& body) {
  std::vector<std::jthread> others;
  for (int thread = 1; thread < count; ++thread) others.emplace_back(body, thread);
  body(0);
}

void Workers::forEachTask(int taskCount, const std::function<void(int task)>& work) const {
  std::atomic<int> nextTask{0};
  int tasksDone = 0;
  std::mutex progressMutex;
  const auto takeTasks = [&](int) {
    for (int task = nextTask++; task < taskCount; task = nextTask++) {
      work(task);
      const std::scoped_lock lock(progressMutex);
      progress_->onProgress(static_cast<double>(++tasksDone) / taskCount);
      if (progress_->cancelled()) nextTask = taskCount;
    }
  };
  onThreads(std::min(threads_, taskCount), takeTasks);
}

void Workers::forEachRange(int count, int rangeSize,
                           const std::function<void(int range, int begin, int end)>& work) const {
  const Workers unobserved(threads_);
  unobserved.forEachTask(rangeCount(count, rangeSize), [&](int range) {
    const int begin = range * rangeSize;
    work(range, begin, std::min(begin + rangeSize, count));
  });
}

}  // namespace rise
