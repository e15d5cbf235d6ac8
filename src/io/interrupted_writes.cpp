#include "io/interrupted_writes.hpp"

#include <limits.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

namespace rise {
namespace {

// A registered name, in memory of its own that a signal handler may read: a
// handler can only unlink what it finds here, without locks or allocation.
struct Slot {
  enum State { Free, Filling, Named };
  std::atomic<int> state{Free};
  char name[PATH_MAX];
};
std::array<Slot, kMostTemporaries> slots;

void removeTemporariesAndStop(int signal) {
  for (Slot& slot : slots)
    if (slot.state.load() == Slot::Named) unlink(slot.name);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void installHandlers() {
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction action {};
    action.sa_handler = &removeTemporariesAndStop;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
  }
}

}  // namespace

void registerTemporary(const std::filesystem::path& temporary) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  const std::string& name = temporary.native();
  if (name.size() >= PATH_MAX) return;
  for (Slot& slot : slots) {
    int expected = Slot::Free;
    if (!slot.state.compare_exchange_strong(expected, Slot::Filling)) continue;
    std::memcpy(slot.name, name.c_str(), name.size() + 1);
    slot.state.store(Slot::Named);
    return;
  }
}

void forgetTemporary(const std::filesystem::path& temporary) {
  for (Slot& slot : slots) {
    int expected = Slot::Named;
    if (slot.state.load() == Slot::Named && temporary.native() == slot.name &&
        slot.state.compare_exchange_strong(expected, Slot::Free))
      return;
  }
}

}  // namespace rise
