#pragma once

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace rise {

// Makes the elements of a container without writing them where no value is
// given: memory that is written before it is read need not be filled first,
// and its pages are then first touched by whoever writes them. The elements
// must be objects whose lifetime may begin in the bytes allocated for them
// (C++20's implicit-lifetime types): trivially default constructible, or
// aggregates, whose default member initializers are then not run; and
// trivially destructible.
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
    if constexpr (sizeof...(Args) == 0) {
      static_assert((std::is_trivially_default_constructible_v<U> ||
                     std::is_aggregate_v<U>)&&std::is_trivially_destructible_v<U>,
                    "an element left unfilled must be an object its bytes can hold");
    } else {
      ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
    }
  }
};

// A vector whose resize leaves the new elements unfilled.
template <typename T>
using UnfilledVector = std::vector<T, LeftUnfilled<T>>;

}  // namespace rise
