#include "ray/bvh_builder.hpp"

#include <algorithm>
#include <array>
#include <atomic>
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
// A subtree of fewer primitives is not worth starting a thread for.
constexpr std::uint32_t kParallelMinimum = 16 * 1024;

// Some of a node's primitives: the box around them, and how many they are.
struct Bin {
  Bounds3 box;
  std::uint32_t count = 0;

  void grow(const Bounds3& other, std::uint32_t otherCount) {
    box.grow(other);
    count += otherCount;
  }
};

// Where a centroid falls among the bins slicing a node's centroids along
// each axis (those of zero extent have no bins).
class Binning {
 public:
  explicit Binning(const Bounds3& centroids)
      : min_(centroids.min), extent_(centroids.extent()), scale_(float(kBins) / extent_) {}

  bool hasBins(int axis) const { return extent_[axis] > 0.0f; }
  int binOf(const Vec3& centroid, int axis) const {
    return std::min(kBins - 1, static_cast<int>((centroid[axis] - min_[axis]) * scale_[axis]));
  }

 private:
  Vec3 min_;
  Vec3 extent_;
  Vec3 scale_;
};

struct Split {
  int axis = -1;        // -1: no plane between bins separates the primitives
  int lastLeftBin = 0;  // bins 0..lastLeftBin go left
  float cost = kInfinity;
  Bounds3 leftBox;
  Bounds3 rightBox;
};

class Builder {
 public:
  Builder(std::vector<BuildPrimitive>& primitives, int threads)
      : primitives_(primitives),
        nodes_(2 * std::max<std::size_t>(primitives.size(), 1) - 1),
        spareThreads_(threads - 1) {}

  BuiltBvh run() {
    BuiltBvh result;
    if (primitives_.empty()) return result;
    Bounds3 box;
    for (const BuildPrimitive& primitive : primitives_) box.grow(primitive.box);
    build(0, 0, static_cast<std::uint32_t>(primitives_.size()), 1, box);
    nodes_.resize(nodeCount_);
    result.nodes = std::move(nodes_);
    result.primitives.reserve(primitives_.size());
    for (const BuildPrimitive& primitive : primitives_) result.primitives.push_back(primitive.ref);
    return result;
  }

 private:
  // Builds the subtree of the primitives in [begin, end), whose box is
  // known, at `node`.
  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth,
             const Bounds3& box) {
    nodes_[node].box = box;
    const std::uint32_t count = end - begin;
    if (count == 1 || depth == kMaxBvhDepth) return makeLeaf(node, begin, end);

    const Bounds3 centroids = centroidBounds(begin, end);
    Split split = bestSplit(begin, end, box, centroids);
    std::uint32_t middle;
    if (split.axis >= 0 && (count > kMaxLeafSize || split.cost < static_cast<float>(count))) {
      const Binning binning(centroids);
      middle = static_cast<std::uint32_t>(
          std::partition(primitives_.begin() + begin, primitives_.begin() + end,
                         [&](const BuildPrimitive& p) {
                           return binning.binOf(p.centroid(), split.axis) <= split.lastLeftBin;
                         }) -
          primitives_.begin());
    } else if (count > kMaxLeafSize) {
      middle = splitAtMedian(begin, end, centroids);
      split.leftBox = boxOf(begin, middle);
      split.rightBox = boxOf(middle, end);
    } else {
      return makeLeaf(node, begin, end);
    }

    const std::uint32_t children = nodeCount_.fetch_add(2);
    nodes_[node].offset = children;
    if (count >= kParallelMinimum && takeSpareThread()) {
      std::thread left([=, this] {
        build(children, begin, middle, depth + 1, split.leftBox);
        ++spareThreads_;
      });
      build(children + 1, middle, end, depth + 1, split.rightBox);
      left.join();
    } else {
      build(children, begin, middle, depth + 1, split.leftBox);
      build(children + 1, middle, end, depth + 1, split.rightBox);
    }
  }

  Bounds3 boxOf(std::uint32_t begin, std::uint32_t end) const {
    Bounds3 box;
    for (std::uint32_t i = begin; i < end; ++i) box.grow(primitives_[i].box);
    return box;
  }

  Bounds3 centroidBounds(std::uint32_t begin, std::uint32_t end) const {
    Bounds3 centroids;
    for (std::uint32_t i = begin; i < end; ++i) centroids.grow(primitives_[i].centroid());
    return centroids;
  }

  // The cheapest plane between bins, along any axis: one pass over the
  // primitives fills the bins of all three axes, then each axis's planes are
  // priced.
  Split bestSplit(std::uint32_t begin, std::uint32_t end, const Bounds3& box,
                  const Bounds3& centroids) const {
    Split best;
    const float parentArea = box.surfaceArea();
    if (!(parentArea > 0.0f)) return best;
    const Binning binning(centroids);
    std::array<std::array<Bin, kBins>, 3> bins{};
    for (std::uint32_t i = begin; i < end; ++i) {
      const Bounds3& primitiveBox = primitives_[i].box;
      const Vec3 centroid = primitives_[i].centroid();
      for (int axis = 0; axis < 3; ++axis)
        if (binning.hasBins(axis)) bins[axis][binning.binOf(centroid, axis)].grow(primitiveBox, 1);
    }
    for (int axis = 0; axis < 3; ++axis)
      if (binning.hasBins(axis)) considerSplits(axis, bins[axis], parentArea, best);
    return best;
  }

  // Sweeps the bins from the right, to know what lies right of each plane,
  // then from the left, pricing each plane.
  static void considerSplits(int axis, const std::array<Bin, kBins>& bins, float parentArea,
                             Split& best) {
    std::array<Bin, kBins> rightOf{};  // rightOf[b]: bins b..kBins-1 together
    Bin right;
    for (int bin = kBins - 1; bin > 0; --bin) {
      right.grow(bins[bin].box, bins[bin].count);
      rightOf[bin] = right;
    }
    Bin left;
    for (int bin = 0; bin < kBins - 1; ++bin) {
      left.grow(bins[bin].box, bins[bin].count);
      const Bin& rest = rightOf[bin + 1];
      if (left.count == 0 || rest.count == 0) continue;
      const float cost = kTraversalCost + (left.box.surfaceArea() * float(left.count) +
                                           rest.box.surfaceArea() * float(rest.count)) /
                                              parentArea;
      if (cost < best.cost) best = {axis, bin, cost, left.box, rest.box};
    }
  }

  // When the bins cannot separate the primitives (their centroids all but
  // coincide), half of them go each way, ordered along the widest axis.
  std::uint32_t splitAtMedian(std::uint32_t begin, std::uint32_t end, const Bounds3& centroids) {
    const int axis = largestAxis(centroids.extent());
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(primitives_.begin() + begin, primitives_.begin() + middle,
                     primitives_.begin() + end,
                     [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                       return a.centroid()[axis] < b.centroid()[axis];
                     });
    return middle;
  }

  void makeLeaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
    nodes_[node].offset = begin;
    nodes_[node].primitiveCount = end - begin;
  }

  bool takeSpareThread() {
    int spare = spareThreads_.load();
    while (spare > 0 && !spareThreads_.compare_exchange_weak(spare, spare - 1)) {
    }
    return spare > 0;
  }

  std::vector<BuildPrimitive>& primitives_;
  std::vector<BvhNode> nodes_;
  std::atomic<std::uint32_t> nodeCount_{1};  // the root
  std::atomic<int> spareThreads_;
};

}  // namespace

BuiltBvh buildBvh(std::vector<BuildPrimitive> primitives, int threads) {
  return Builder(primitives, std::max(threads, 1)).run();
}

}  // namespace rise
