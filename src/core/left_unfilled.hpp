#pragma once

#include <memory>
#include <utility>
#include <vector>

namespace rise {

// Makes the elements of a container without a value where none is given, as
// `new T` does: memory that is written before it is read need not be filled
// first, and its pages are then first touched by whoever writes them.
template <typename T>
struct LeftUnfilled : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = LeftUnfilled<U>;
  };
  LeftUnfilled() = default;
  template <typename U>
  LeftUnfilled(const LeftUnfilled<U>&) {}

  template <typename U, typename... Args>
  void construct(U* place, Args&&... args) {
    if constexpr (sizeof...(Args) == 0)
      ::new (static_cast<void*>(place)) U;
    else
      ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
  }
};

// A vector whose resize leaves the new elements unfilled.
template <typename T>
using UnfilledVector = std::vector<T, LeftUnfilled<T>>;

}  // namespace rise
