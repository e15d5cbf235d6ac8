// Depth sort's list of the polygons waiting to be painted (depth_sort.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/polygon_relations.hpp"

namespace rise {

// The polygons waiting to be painted, the next at the front. Behind the
// polygons moved to the front or cut there, the rest stays sorted by farthest
// depth, so that the search for polygons the front one may hide can stop at
// the first of them that lies wholly nearer.
class WaitingList {
 public:
  WaitingList(std::vector<int> sorted, const std::vector<Extent>& extents)
      : list_(std::move(sorted)), extents_(extents) {}

  bool isEmpty() const { return head_ == list_.size(); }
  int front() const { return list_[head_]; }
  // Positions run from the front, 0, to size() - 1.
  std::size_t size() const { return list_.size() - head_; }
  int at(std::size_t position) const { return list_[head_ + position]; }
  bool isSortedAt(std::size_t position) const { return head_ + position >= sortedFrom_; }
  std::size_t find(int piece) const {
    return static_cast<std::size_t>(std::find(list_.begin() + head_, list_.end(), piece) -
                                    list_.begin()) -
           head_;
  }

  // The pairs of waiting polygons whose depths overlap, as the list is when
  // sorted: the comparisons that painting them takes at the least, as each
  // is compared with those after it until one lies wholly nearer.
  std::uint64_t overlappingPairs() const {
    std::vector<float> farthest;
    farthest.reserve(list_.size());
    for (int piece : list_) farthest.push_back(extents_[piece].farthest);
    std::uint64_t pairs = 0;
    for (std::size_t i = 0; i < list_.size(); ++i) {
      const auto after = farthest.begin() + static_cast<std::ptrdiff_t>(i) + 1;
      pairs += static_cast<std::uint64_t>(
          std::lower_bound(after, farthest.end(), extents_[list_[i]].nearest) - after);
    }
    return pairs;
  }

  void popFront() { sortedFrom_ = std::max(sortedFrom_, ++head_); }

  void moveToFront(std::size_t position) {
    const auto moved = list_.begin() + static_cast<std::ptrdiff_t>(head_ + position);
    if (isSortedAt(position)) ++sortedFrom_;
    std::rotate(list_.begin() + static_cast<std::ptrdiff_t>(head_), moved, moved + 1);
  }

  // Puts two pieces in place of the polygon at `position`: at the front, both
  // at the front; in the sorted part, each where its depth sorts it.
  void replace(std::size_t position, int first, int second) {
    const std::size_t index = head_ + position;
    if (position == 0 || !isSortedAt(position)) {
      list_[index] = first;
      list_.insert(list_.begin() + static_cast<std::ptrdiff_t>(index) + 1, second);
      sortedFrom_ = std::max(sortedFrom_ + 1, index + 2);
      return;
    }
    list_.erase(list_.begin() + static_cast<std::ptrdiff_t>(index));
    for (int piece : {first, second}) {
      const auto place = std::upper_bound(
          list_.begin() + static_cast<std::ptrdiff_t>(sortedFrom_), list_.end(), piece,
          [&](int a, int b) { return extents_[a].farthest < extents_[b].farthest; });
      list_.insert(place, piece);
    }
  }

 private:
  std::vector<int> list_;
  const std::vector<Extent>& extents_;
  std::size_t head_ = 0;
  std::size_t sortedFrom_ = 0;
};

}  // namespace rise
