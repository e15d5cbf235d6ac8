// Work shared among threads. Every parallel part of RISE goes through here:
// an algorithm cuts its work into tasks (tiles of the image, bands of
// scanlines, ranges of polygons, windows still to subdivide) and hands them to
// its Workers, and never sees a thread. Results do not depend on the number of
// threads: tasks are numbered, what each computes is kept apart and combined
// in task order.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <vector>

#include "core/image.hpp"

namespace rise {

// Watches long work from outside: progress for a bar, cancellation for an
// interactive front end. Called from the worker threads, one call at a time,
// but for onRegionDone.
class Progress {
 public:
  virtual ~Progress() = default;
  virtual void onProgress(double /*fractionDone*/) {}
  virtual bool cancelled() const { return false; }
  // The part `region` of the image the work makes is finished (a tile, a
  // band): called by the task that finished it, while other tasks may run.
  virtual void onRegionDone(const PixelRect& /*region*/) {}
};

// The number of threads to use: `requested`, or one per hardware thread when
// it is 0.
int resolveThreadCount(int requested);

class Workers {
 public:
  // `threads` threads (0: one per hardware thread); progress and
  // cancellation are reported to `progress`, or to nobody.
  explicit Workers(int threads);
  Workers(int threads, Progress& progress);

  int threads() const { return threads_; }
  bool cancelled() const { return progress_->cancelled(); }
  // Called by a task that has finished the pixels of `region`.
  void regionDone(const PixelRect& region) const { progress_->onRegionDone(region); }

  // Calls work(task) once for every task of [0, taskCount), each thread
  // taking the next task not yet taken; reports the share of tasks done
  // after each, and stops handing out tasks once cancelled.
  void forEachTask(int taskCount, const std::function<void(int task)>& work) const;

  // The same, each task adding into a part of its own; the parts are then
  // summed in task order, so that the total is the same whatever thread did
  // what.
  template <typename Part, typename Work>
  Part sumOverTasks(int taskCount, const Work& work) const {
    std::vector<Part> parts(static_cast<std::size_t>(taskCount));
    forEachTask(taskCount, [&](int task) { work(task, parts[static_cast<std::size_t>(task)]); });
    Part total{};
    for (const Part& part : parts) total += part;
    return total;
  }

  // Calls work(range, begin, end) for the ranges [begin, end) of `rangeSize`
  // consecutive items of [0, count), numbered in order from 0 (the last may
  // be shorter): the steps of a long list, such as a mesh's vertices, which
  // report no progress of their own.
  void forEachRange(int count, int rangeSize,
                    const std::function<void(int range, int begin, int end)>& work) const;

  // Drains a work list whose items may add items: process(item, part, more)
  // handles one item, counting into the part of the thread that runs it and
  // appending to `more` the items it gives rise to, which the threads take
  // in turn. An item is handed out only after the one that added it is done.
  // The parts are summed at the end, so they must hold what adds up in any
  // order (counts). Progress is the share of the first items' work done,
  // each item's share split evenly among the items it adds.
  template <typename Item, typename Part, typename Process>
  Part drain(std::vector<Item> items, const Process& process) const;

  // The number of ranges forEachRange makes.
  static int rangeCount(int count, int rangeSize) { return (count + rangeSize - 1) / rangeSize; }

 private:
  // Runs body(thread) for thread = 0 to count - 1, each on a thread of its
  // own (the first on this one), and returns when all have returned.
  static void onThreads(int count, const std::function<void(int thread)>& body);

  int threads_;
  Progress* progress_;
};

template <typename Item, typename Part, typename Process>
Part Workers::drain(std::vector<Item> items, const Process& process) const {
  struct Pending {
    Item item;
    double share;  // of the whole work
  };
  // Taken last in, first out: the list then holds a few items per level of
  // a recursion instead of whole levels.
  std::vector<Pending> pending;
  for (Item& item : items)
    pending.push_back({std::move(item), 1.0 / static_cast<double>(items.size())});
  std::vector<Part> parts(static_cast<std::size_t>(threads_));
  std::mutex mutex;
  std::condition_variable changed;
  int inHand = 0;
  double done = 0.0;
  onThreads(threads_, [&](int thread) {
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return !pending.empty() || inHand == 0 || progress_->cancelled(); });
      if (pending.empty() || progress_->cancelled()) break;
      Pending next = std::move(pending.back());
      pending.pop_back();
      ++inHand;
      lock.unlock();
      std::vector<Item> more;
      process(std::move(next.item), parts[static_cast<std::size_t>(thread)], more);
      lock.lock();
      --inHand;
      for (Item& item : more)
        pending.push_back({std::move(item), next.share / static_cast<double>(more.size())});
      if (more.empty()) progress_->onProgress(done += next.share);
      changed.notify_all();
    }
  });
  Part total{};
  for (const Part& part : parts) total += part;
  return total;
}

}  // namespace rise
