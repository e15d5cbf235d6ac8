#include "ray/bvh_builder.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <mutex>
#include <thread>

namespace rise {
namespace {

// Slices along each axis: more make a barely better tree, more slowly.
constexpr int kBins = 16;
// The cost of visiting a node, in primitive tests: one more box test, and
// the bookkeeping around it.
constexpr float kTraversalCost = 1.0f;
// A node of more primitives is split even when the heuristic would rather not.
constexpr std::uint32_t kMaxLeafSize = 8;
// A node of fewer primitives is not worth starting a thread for, to bin a
// share of it or to build its subtree.
constexpr std::uint32_t kParallelMinimum = 16 * 1024;

// Four floats, or four ints, that arithmetic treats at once, as one SIMD
// register (GCC's and Clang's vector extensions): a box's corner, binned
// along its three axes at once.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

Float4 min(Float4 a, Float4 b) { return a < b ? a : b; }
Float4 max(Float4 a, Float4 b) { return a > b ? a : b; }

// A row of a primitive's box with zero in the fourth lane, for the bits of
// the reference there would make a denormal float, on which arithmetic takes
// a hundred times as long.
Float4 loadRow(const float* row) {
  Float4 loaded;
  std::memcpy(&loaded, row, sizeof(loaded));
  loaded[3] = 0.0f;
  return loaded;
}
Float4 loadLower(const BuildPrimitive& primitive) { return loadRow(primitive.lower); }
Float4 loadUpper(const BuildPrimitive& primitive) { return loadRow(primitive.upper); }
Float4 centroidOf(const BuildPrimitive& primitive) {
  return (loadLower(primitive) + loadUpper(primitive)) * 0.5f;
}

// A box as two rows of four floats, of which the first three count.
struct alignas(16) FourBox {
  Float4 lower = Float4{} + kInfinity;
  Float4 upper = Float4{} - kInfinity;

  void grow(Float4 lowerCorner, Float4 upperCorner) {
    lower = min(lower, lowerCorner);
    upper = max(upper, upperCorner);
  }
  void grow(const FourBox& other) { grow(other.lower, other.upper); }
  float surfaceArea() const {
    const Float4 extent = upper - lower;
    return 2.0f * (extent[0] * extent[1] + extent[1] * extent[2] + extent[2] * extent[0]);
  }
  Bounds3 bounds() const {
    return {Vec3(lower[0], lower[1], lower[2]), Vec3(upper[0], upper[1], upper[2])};
  }
};

// Where a centroid falls among the bins slicing a node's centroids along
// each axis (those of zero extent have no bins: every centroid falls in their
// first).
class Binning {
 public:
  explicit Binning(const FourBox& centroids) : min_(centroids.lower) {
    const Float4 extent = centroids.upper - centroids.lower;
    for (int axis = 0; axis < 3; ++axis) {
      hasBins_[axis] = extent[axis] > 0.0f;
      scale_[axis] = hasBins_[axis] ? float(kBins) / extent[axis] : 0.0f;
    }
    scale_[3] = 0.0f;
  }

  bool hasBins(int axis) const { return hasBins_[axis]; }

  // The bin of the primitive's centroid along one axis.
  int binOf(const BuildPrimitive& primitive, int axis) const {
    const float centroid = (primitive.lower[axis] + primitive.upper[axis]) * 0.5f;
    return std::min(kBins - 1, static_cast<int>((centroid - min_[axis]) * scale_[axis]));
  }

  // The bin of the centroid along each of the three axes, in three lanes.
  Int4 binsOf(Float4 centroid) const {
    const Int4 bins = __builtin_convertvector((centroid - min_) * scale_, Int4);
    return bins < kBins - 1 ? bins : Int4{} + (kBins - 1);
  }

 private:
  Float4 min_;
  Float4 scale_{};
  std::array<bool, 3> hasBins_{};
};

// A node's primitives sorted into the bins of each axis: the box around each
// bin's primitives, and how many they are.
struct Bins {
  std::array<std::array<FourBox, kBins>, 3> boxes{};
  std::array<std::array<std::uint32_t, kBins>, 3> counts{};

  void add(std::span<const BuildPrimitive> primitives, const Binning& binning) {
    for (const BuildPrimitive& primitive : primitives) {
      const Float4 lower = loadLower(primitive), upper = loadUpper(primitive);
      const Int4 bins = binning.binsOf((lower + upper) * 0.5f);
      for (int axis = 0; axis < 3; ++axis) {
        boxes[axis][bins[axis]].grow(lower, upper);
        ++counts[axis][bins[axis]];
      }
    }
  }

  void add(const Bins& other) {
    for (int axis = 0; axis < 3; ++axis)
      for (int bin = 0; bin < kBins; ++bin) {
        boxes[axis][bin].grow(other.boxes[axis][bin]);
        counts[axis][bin] += other.counts[axis][bin];
      }
  }
};

struct Split {
  int axis = -1;        // -1: no plane between bins separates the primitives
  int lastLeftBin = 0;  // bins 0..lastLeftBin go left
  float cost = kInfinity;
};

// A run of primitives [begin, end) and the boxes around them and around
// their centroids.
struct Range {
  std::uint32_t begin;
  std::uint32_t end;
  FourBox box;
  FourBox centroids;

  std::uint32_t count() const { return end - begin; }
};

class Builder {
 public:
  // Builds the subtree of the primitives [begin, end), whose root is `depth`
  // nodes below the whole tree's.
  Builder(std::span<BuildPrimitive> primitives, std::uint32_t begin, std::uint32_t end, int depth,
          int threads, std::uint32_t unbuiltAtMost)
      : primitives_(primitives),
        begin_(begin),
        end_(end),
        depth_(depth),
        nodes_(std::make_unique_for_overwrite<BvhNode[]>(2 * std::size_t{end - begin} - 1)),
        spareThreads_(threads - 1),
        unbuiltAtMost_(unbuiltAtMost) {}

  BuiltBvh run() {
    build(0, rangeOf(begin_, end_), depth_);
    return {std::move(nodes_), nodeCount_.load(), std::move(unbuilt_)};
  }

 private:
  // Builds the subtree of the primitives of `range` at `node`.
  void build(std::uint32_t node, const Range& range, int depth) {
    nodes_[node].box = range.box.bounds();
    const std::uint32_t count = range.count();
    if (count == 1 || depth == kMaxBvhDepth) return makeLeaf(node, range);
    if (count <= unbuiltAtMost_) return leaveUnbuilt(node, range, depth);

    const Binning binning(range.centroids);
    const Split split = bestSplit(range, binning);
    std::array<Range, 2> children;
    if (split.axis >= 0 && (count > kMaxLeafSize || split.cost < static_cast<float>(count))) {
      children = partition(range, binning, split);
    } else if (count > kMaxLeafSize) {
      children = splitAtMedian(range);
    } else {
      return makeLeaf(node, range);
    }

    const std::uint32_t first = nodeCount_.fetch_add(2);
    nodes_[node].offset = first;
    nodes_[node].primitiveCount = 0;
    if (count >= kParallelMinimum && takeSpareThreads(1) == 1) {
      std::thread left([&, first, depth] {
        build(first, children[0], depth + 1);
        ++spareThreads_;
      });
      build(first + 1, children[1], depth + 1);
      left.join();
    } else {
      build(first, children[0], depth + 1);
      build(first + 1, children[1], depth + 1);
    }
  }

  // The cheapest plane between bins, along any axis: one pass over the
  // primitives fills the bins of all three axes, then each axis's planes are
  // priced. A large node's primitives are binned in shares, one a thread.
  Split bestSplit(const Range& range, const Binning& binning) {
    Split best;
    const float parentArea = range.box.surfaceArea();
    if (!(parentArea > 0.0f)) return best;
    const Bins bins = binnedOnThreads(range, binning);
    for (int axis = 0; axis < 3; ++axis)
      if (binning.hasBins(axis)) considerSplits(axis, bins, parentArea, best);
    return best;
  }

  Bins binnedOnThreads(const Range& range, const Binning& binning) {
    const std::span<const BuildPrimitive> all(primitives_.data() + range.begin, range.count());
    Bins bins;
    const int helpers = takeSpareThreads(static_cast<int>(range.count() / kParallelMinimum) - 1);
    if (helpers == 0) {
      bins.add(all, binning);
      return bins;
    }
    const std::size_t share = all.size() / static_cast<std::size_t>(helpers + 1);
    std::vector<Bins> helperBins(static_cast<std::size_t>(helpers));
    std::vector<std::thread> threads;
    for (int helper = 0; helper < helpers; ++helper)
      threads.emplace_back([&, helper] {
        helperBins[helper].add(all.subspan(share * (helper + 1), share), binning);
      });
    bins.add(all.first(share), binning);
    bins.add(all.subspan(share * (helpers + 1)), binning);  // what the shares left over
    for (int helper = 0; helper < helpers; ++helper) {
      threads[helper].join();
      bins.add(helperBins[helper]);
    }
    spareThreads_ += helpers;
    return bins;
  }

  // Sweeps the bins that hold primitives from the right, to know what lies
  // right of each plane, then from the left, pricing each plane. A plane
  // after an empty bin parts the primitives as the plane before it does, and
  // is not priced again.
  static void considerSplits(int axis, const Bins& bins, float parentArea, Split& best) {
    const auto& boxes = bins.boxes[axis];
    const auto& counts = bins.counts[axis];
    std::array<int, kBins> filled;  // the bins that hold primitives, in order
    int filledCount = 0;
    for (int bin = 0; bin < kBins; ++bin)
      if (counts[bin] > 0) filled[filledCount++] = bin;
    std::array<FourBox, kBins> rightBoxes;  // rightBoxes[i]: around filled[i..]
    std::array<std::uint32_t, kBins> rightCounts;
    FourBox right;
    std::uint32_t rightCount = 0;
    for (int i = filledCount - 1; i > 0; --i) {
      right.grow(boxes[filled[i]]);
      rightCount += counts[filled[i]];
      rightBoxes[i] = right;
      rightCounts[i] = rightCount;
    }
    FourBox left;
    std::uint32_t leftCount = 0;
    for (int i = 0; i + 1 < filledCount; ++i) {
      left.grow(boxes[filled[i]]);
      leftCount += counts[filled[i]];
      const float cost =
          kTraversalCost + (left.surfaceArea() * float(leftCount) +
                            rightBoxes[i + 1].surfaceArea() * float(rightCounts[i + 1])) /
                               parentArea;
      if (cost < best.cost) best = {axis, filled[i], cost};
    }
  }

  // Moves the primitives of the split's left bins before those of its right
  // ones, noting the box around each side and around its centroids as it
  // goes.
  std::array<Range, 2> partition(const Range& range, const Binning& binning, const Split& split) {
    std::array<Range, 2> sides{Range{range.begin, 0, {}, {}}, Range{0, range.end, {}, {}}};
    const auto goesLeft = [&](const BuildPrimitive& primitive) {
      return binning.binOf(primitive, split.axis) <= split.lastLeftBin;
    };
    const auto note = [](Range& side, const BuildPrimitive& primitive) {
      const Float4 lower = loadLower(primitive), upper = loadUpper(primitive);
      const Float4 centroid = (lower + upper) * 0.5f;
      side.box.grow(lower, upper);
      side.centroids.grow(centroid, centroid);
    };
    std::uint32_t left = range.begin, right = range.end;
    while (true) {
      while (left < right && goesLeft(primitives_[left])) note(sides[0], primitives_[left++]);
      while (left < right && !goesLeft(primitives_[right - 1]))
        note(sides[1], primitives_[--right]);
      if (left == right) break;
      std::swap(primitives_[left], primitives_[right - 1]);
      note(sides[0], primitives_[left++]);
      note(sides[1], primitives_[--right]);
    }
    sides[0].end = sides[1].begin = left;
    return sides;
  }

  // When the bins cannot separate the primitives (their centroids all but
  // coincide), half of them go each way, ordered along the widest axis.
  std::array<Range, 2> splitAtMedian(const Range& range) {
    const int axis = largestAxis(range.centroids.bounds().extent());
    const std::uint32_t middle = range.begin + range.count() / 2;
    std::nth_element(primitives_.begin() + range.begin, primitives_.begin() + middle,
                     primitives_.begin() + range.end,
                     [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                       return centroidOf(a)[axis] < centroidOf(b)[axis];
                     });
    return {rangeOf(range.begin, middle), rangeOf(middle, range.end)};
  }

  Range rangeOf(std::uint32_t begin, std::uint32_t end) const {
    Range range{begin, end, {}, {}};
    for (std::uint32_t i = begin; i < end; ++i) {
      range.box.grow(loadLower(primitives_[i]), loadUpper(primitives_[i]));
      const Float4 centroid = centroidOf(primitives_[i]);
      range.centroids.grow(centroid, centroid);
    }
    return range;
  }

  void makeLeaf(std::uint32_t node, const Range& range) {
    nodes_[node].offset = range.begin;
    nodes_[node].primitiveCount = range.count();
  }

  void leaveUnbuilt(std::uint32_t node, const Range& range, int depth) {
    const std::lock_guard lock(unbuiltMutex_);
    nodes_[node].offset = static_cast<std::uint32_t>(unbuilt_.size());
    nodes_[node].primitiveCount = kUnbuiltSubtree;
    unbuilt_.push_back({range.begin, range.end, depth});
  }

  // Takes up to `wanted` of the threads not working now; returns how many.
  int takeSpareThreads(int wanted) {
    int spare = spareThreads_.load();
    int taken = 0;
    do {
      taken = std::max(0, std::min(spare, wanted));
    } while (taken > 0 && !spareThreads_.compare_exchange_weak(spare, spare - taken));
    return taken;
  }

  std::span<BuildPrimitive> primitives_;
  const std::uint32_t begin_;
  const std::uint32_t end_;
  const int depth_;
  std::unique_ptr<BvhNode[]> nodes_;
  std::atomic<std::uint32_t> nodeCount_{1};  // the root
  std::atomic<int> spareThreads_;
  const std::uint32_t unbuiltAtMost_;
  std::mutex unbuiltMutex_;
  std::vector<UnbuiltSubtree> unbuilt_;
};

}  // namespace

BuiltBvh buildBvh(std::span<BuildPrimitive> primitives, int threads, std::uint32_t unbuiltAtMost) {
  if (primitives.empty()) return {};
  const auto count = static_cast<std::uint32_t>(primitives.size());
  return Builder(primitives, 0, count, 1, std::max(threads, 1),
                 count > unbuiltAtMost ? unbuiltAtMost : 0)
      .run();
}

BuiltBvh buildSubtree(std::span<BuildPrimitive> primitives, const UnbuiltSubtree& subtree) {
  return Builder(primitives, subtree.begin, subtree.end, subtree.depth, 1, 0).run();
}

}  // namespace rise
