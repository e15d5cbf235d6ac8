#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace rise {

// What a render measured, as named numbers in the order they were added:
// time, rays by kind, intersection tests... The CLI prints them, --stats
// writes them as JSON, and the compare table puts algorithms side by side.
// A count per unit of another (intersection tests per ray): 0 where there
// are none of those units, as where a hybrid finds every first hit in its
// item buffer and traces no ray, so that a table shows no "inf" or "nan".
inline double perEach(double count, double units) { return units > 0.0 ? count / units : 0.0; }

class Stats {
 public:
  void add(std::string name, double value) { entries_.emplace_back(std::move(name), value); }

  const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }

  // Adds each of `other`'s values to the value of the same name, or appends
  // it: the counters of several passes summed.
  void accumulate(const Stats& other) {
    for (const auto& added : other.entries_) {
      auto same = std::find_if(entries_.begin(), entries_.end(),
                               [&](const auto& entry) { return entry.first == added.first; });
      if (same == entries_.end())
        entries_.push_back(added);
      else
        same->second += added.second;
    }
  }

  // The value of `name`, or 0 when it was not recorded.
  double value(const std::string& name) const {
    for (const auto& [key, v] : entries_)
      if (key == name) return v;
    return 0.0;
  }

 private:
  std::vector<std::pair<std::string, double>> entries_;
};

}  // namespace rise
