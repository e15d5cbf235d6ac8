#include "render/step_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace rise {

const char* toString(RayKind kind) {
  switch (kind) {
    case RayKind::Primary:
      return "primary";
    case RayKind::Shadow:
      return "shadow";
    case RayKind::Reflection:
      return "reflection";
    case RayKind::Refraction:
      return "refraction";
  }
  return "?";
}

void StepRecorder::record(Step step, std::int64_t order, int part) {
  const std::scoped_lock lock(mutex_);
  recorded_.push_back({order, part, std::move(step)});
}

bool StepRecorder::wantsDetail(const PixelRect& bounds) {
  bool wanted = !budget_.region || !bounds.intersection(*budget_.region).isEmpty();
  if (wanted) {
    const std::scoped_lock lock(mutex_);
    wanted = recorded_.size() < kMostDetailedSteps;
  }
  if (!wanted) ++notDetailed_;
  return wanted;
}

void StepRecorder::recordTree(RayTree tree) {
  const std::scoped_lock lock(mutex_);
  trees_.push_back(std::move(tree));
}

namespace {

template <typename T>
void append(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

// A later part of the same step: its words and numbers are the first part's,
// its new shapes and its pixels are added.
void join(Step& step, const Step& part) {
  for (const StepShape& shape : part.shapes)
    if (std::find(step.shapes.begin(), step.shapes.end(), shape) == step.shapes.end())
      step.shapes.push_back(shape);
  append(step.writes, part.writes);
  append(step.settled, part.settled);
  for (std::size_t table = 0; table < std::min(step.tables.size(), part.tables.size()); ++table)
    append(step.tables[table].rows, part.tables[table].rows);
}

bool touches(const Step& step, const PixelRect& region) {
  const PixelRect bounds = boundsOf(step);
  return bounds.isEmpty() || !bounds.intersection(region).isEmpty();
}

}  // namespace

void StepTally::add(const Step& step) {
  const auto kind = std::find_if(kinds.begin(), kinds.end(),
                                 [&](const auto& counted) { return counted.first == step.kind; });
  if (kind == kinds.end())
    kinds.emplace_back(step.kind, 1);
  else
    ++kind->second;
  for (const PixelWrite& write : step.writes) ++(write.kept ? painted : hidden);
  for (const PixelRect& area : step.settled)
    settled += static_cast<std::uint64_t>(area.width()) * static_cast<std::uint64_t>(area.height());
}

std::vector<Step> StepRecorder::allSteps() const {
  std::vector<const Recorded*> ordered;
  {
    const std::scoped_lock lock(mutex_);
    for (const Recorded& recorded : recorded_) ordered.push_back(&recorded);
  }
  std::stable_sort(ordered.begin(), ordered.end(), [](const Recorded* a, const Recorded* b) {
    return a->order != b->order ? a->order < b->order : a->part < b->part;
  });
  std::vector<Step> steps;
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    if (i > 0 && ordered[i]->order == ordered[i - 1]->order)
      join(steps.back(), ordered[i]->step);
    else
      steps.push_back(ordered[i]->step);
  }
  return steps;
}

namespace {

// A step's depth in a hierarchy, when it has one (Warnock's windows).
std::optional<int> levelOf(const Step& step) {
  for (const auto& [name, value] : step.values)
    if (name == "level") return static_cast<int>(value);
  return std::nullopt;
}

// Of the candidates, every which-th of a group is kept: of all of them
// alike; or, for steps that have a level, the kept steps shared among the
// levels, the shallow ones (few steps, large windows) kept whole and the
// rest split evenly, so that every level shows.
std::map<int, int> stridesByLevel(const std::vector<const Step*>& candidates, int keep) {
  std::map<int, int> counts;
  for (const Step* step : candidates) ++counts[levelOf(*step).value_or(0)];
  std::map<int, int> strides;
  int left = keep;
  int levelsLeft = static_cast<int>(counts.size());
  for (const auto& [level, count] : counts) {
    const int quota = std::max(1, left / levelsLeft--);
    strides[level] = (count + quota - 1) / quota;
    left -= (count + strides[level] - 1) / strides[level];
  }
  return strides;
}

}  // namespace

std::vector<Step> StepRecorder::keptSteps() const {
  std::vector<Step> steps = allSteps();
  const auto inRegion = [&](const Step& step) {
    return !budget_.region || touches(step, *budget_.region);
  };
  std::vector<const Step*> candidates;
  for (const Step& step : steps)
    if (inRegion(step)) candidates.push_back(&step);
  const bool byLevel = budget_.every == 0 && !candidates.empty() &&
                       std::all_of(candidates.begin(), candidates.end(),
                                   [](const Step* step) { return levelOf(*step).has_value(); });
  const std::map<int, int> strides =
      byLevel ? stridesByLevel(candidates, StepBudget::kDefaultKeptSteps)
              : std::map<int, int>{
                    {0, budget_.every > 0 ? budget_.every
                                          : std::max(1, static_cast<int>(std::ceil(
                                                            static_cast<double>(candidates.size()) /
                                                            StepBudget::kDefaultKeptSteps)))}};
  std::map<int, std::int64_t> seen;  // candidates met, by level
  const auto keeps = [&](const Step& step) {
    const int level = byLevel ? *levelOf(step) : 0;
    return inRegion(step) && seen[level]++ % strides.at(level) == 0;
  };
  std::vector<Step> kept;
  Step left;  // what the steps left out since the last kept one changed
  int skipped = 0;
  StepTally tally;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    Step& step = steps[i];
    tally.add(step);
    const bool last = i + 1 == steps.size();
    const bool keep = keeps(step) || last;
    if (!keep) {
      append(left.writes, step.writes);
      append(left.settled, step.settled);
      ++skipped;
      continue;
    }
    step.writesBefore = std::move(left.writes);
    step.settledBefore = std::move(left.settled);
    step.skippedBefore = skipped;
    step.soFar = tally;
    kept.push_back(std::move(step));
    left = {};
    skipped = 0;
  }
  return kept;
}

std::vector<RayTree> StepRecorder::trees() const {
  const std::scoped_lock lock(mutex_);
  std::vector<RayTree> trees = trees_;
  std::stable_sort(trees.begin(), trees.end(),
                   [](const RayTree& a, const RayTree& b) { return a.sample < b.sample; });
  return trees;
}

PixelRect boundsOf(const Step& step) {
  Vec2 low(kInfinity), high(-kInfinity);
  for (const StepShape& shape : step.shapes) {
    for (const Vec2& point : shape.points) {
      low = glm::min(low, point);
      high = glm::max(high, point);
    }
  }
  for (const PixelWrite& write : step.writes) {
    low = glm::min(low, Vec2(static_cast<float>(write.x), static_cast<float>(write.y)));
    high = glm::max(high, Vec2(static_cast<float>(write.x + 1), static_cast<float>(write.y + 1)));
  }
  for (const PixelRect& rect : step.settled) {
    low = glm::min(low, Vec2(static_cast<float>(rect.x0), static_cast<float>(rect.y0)));
    high = glm::max(high, Vec2(static_cast<float>(rect.x1), static_cast<float>(rect.y1)));
  }
  if (low.x > high.x) return {0, 0, 0, 0};
  return {static_cast<int>(std::floor(low.x)), static_cast<int>(std::floor(low.y)),
          static_cast<int>(std::ceil(high.x)), static_cast<int>(std::ceil(high.y))};
}

}  // namespace rise
