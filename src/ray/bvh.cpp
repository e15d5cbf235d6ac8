#include "ray/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "core/parallel.hpp"
#include "ray/bvh_traversal.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle.hpp"

namespace rise {
namespace {

using namespace bvh_traversal;

// Every primitive's box is widened on every side by this fraction of its
// farthest coordinate from the origin, so that a hit the primitive's own test
// finds on its very edge is never outside its box through rounding. The
// same on every axis: a triangle in the plane y = 0 has a box of no height,
// which rounding in the slab test could otherwise put just beyond the hit.
constexpr float kBoxAllowance = 1e-6f;

Bounds3 widened(const Bounds3& box) {
  const float allowance =
      kBoxAllowance * maxComponent(glm::max(glm::abs(box.min), glm::abs(box.max)));
  return {box.min - Vec3(allowance), box.max + Vec3(allowance)};
}

// A share of a loop is not worth a thread of its own below this many steps.
constexpr std::size_t kMinimumShare = 16 * 1024;

// Calls work(begin, end) on shares of [0, count) that split it, each on a
// thread of its own, on up to `threads` threads.
template <typename Work>
void inShares(std::size_t count, int threads, Work&& work) {
  const std::size_t shares =
      std::clamp<std::size_t>(count / kMinimumShare, 1, static_cast<std::size_t>(threads));
  std::vector<std::thread> helpers;
  for (std::size_t share = 1; share < shares; ++share)
    helpers.emplace_back(
        [&, share] { work(count * share / shares, count * (share + 1) / shares); });
  work(0, count / shares);
  for (std::thread& helper : helpers) helper.join();
}

UnfilledVector<BuildPrimitive> primitivesOf(const std::vector<const Shape*>& shapes,
                                            const std::vector<bool>& bounded, int threads) {
  std::vector<std::size_t> firstOf{0};  // of each shape, among all the primitives
  for (std::size_t shape = 0; shape < shapes.size(); ++shape)
    firstOf.push_back(
        firstOf.back() +
        (bounded[shape] ? static_cast<std::size_t>(shapes[shape]->primitiveCount()) : 0));
  UnfilledVector<BuildPrimitive> primitives(firstOf.back());
  inShares(primitives.size(), threads, [&](std::size_t begin, std::size_t end) {
    auto shape = static_cast<std::size_t>(std::upper_bound(firstOf.begin(), firstOf.end(), begin) -
                                          firstOf.begin() - 1);
    for (std::size_t i = begin; i < end; ++i) {
      while (i == firstOf[shape + 1]) ++shape;
      const auto primitive = static_cast<int>(i - firstOf[shape]);
      primitives[i] = BuildPrimitive(
          widened(shapes[shape]->primitiveBounds(primitive)),
          PrimitiveRef{static_cast<std::uint32_t>(shape), static_cast<std::uint32_t>(primitive)});
    }
  });
  return primitives;
}

// Four floats that arithmetic treats at once, as one SIMD register: the
// vector extension GCC and clang share, which compiles `a > b ? a : b` to one
// instruction on any processor with vectors of four floats.
using FourFloats = float __attribute__((vector_size(4 * sizeof(float))));
using FourInts = std::int32_t __attribute__((vector_size(4 * sizeof(std::int32_t))));
static_assert(kWideBvhWidth == 4, "a node's boxes fill one FourFloats an axis");

FourFloats broadcast(float value) { return FourFloats{value, value, value, value}; }

FourFloats fourFloatsAt(const float* first) {
  FourFloats four;
  std::memcpy(&four, first, sizeof four);
  return four;
}

// A ray made ready for many box tests: the slab test (Kay and Kajiya 1986)
// divides by the direction, so its inverse is computed once, and along each
// axis the ray enters a box by the face it looks at first, known once from
// the direction's sign.
class BoxRay {
 public:
  explicit BoxRay(const Ray& ray)
      : origin_(ray.origin),
        inverseDirection_(1.0f / ray.direction),
        entersByMax_(glm::lessThan(inverseDirection_, Vec3(0.0f))) {}

  // Where the ray enters each of the node's children's boxes within
  // (tMin, tMax), or infinity where it misses one there: each step below is
  // one instruction on the four boxes at once. A direction component of zero
  // makes an infinite inverse; for an origin on a box's face that gives
  // 0 * infinity = NaN, which max and min drop (max(a, b) is a > b ? a : b,
  // which is b when a is NaN), so that the ray lying in the face counts as
  // inside. The exit is pushed out by kRobustExit. Always inlined: called
  // apart, it would pass its result through memory.
  [[gnu::always_inline]] FourFloats entries(const WideBvhNode& node, float tMin, float tMax) const {
    FourFloats enter = broadcast(tMin);
    FourFloats exit = broadcast(kInfinity);
    for (int axis = 0; axis < 3; ++axis) {
      const float* nearFaces = entersByMax_[axis] ? node.upper[axis] : node.lower[axis];
      const float* farFaces = entersByMax_[axis] ? node.lower[axis] : node.upper[axis];
      const FourFloats nearT = (fourFloatsAt(nearFaces) - origin_[axis]) * inverseDirection_[axis];
      const FourFloats farT = (fourFloatsAt(farFaces) - origin_[axis]) * inverseDirection_[axis];
      enter = maximum(nearT, enter);
      exit = minimum(farT, exit);
    }
    return enter <= minimum(exit * kRobustExit, broadcast(tMax)) ? enter : broadcast(kInfinity);
  }

 private:
  Vec3 origin_;
  Vec3 inverseDirection_;
  glm::bvec3 entersByMax_;
};

// The bits of the children whose entries are finite, the ones a ray meets:
// one instruction where the processor has it.
unsigned childrenMet(FourFloats entries) {
  const FourInts met = entries != broadcast(kInfinity);
#if defined(__SSE__)
  return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(met)));
#else
  const FourInts bits = met & FourInts{1, 2, 4, 8};
  return static_cast<unsigned>(bits[0] | bits[1] | bits[2] | bits[3]);
#endif
}

// A child that traversal has yet to enter: an inner node, or a leaf.
struct PendingChild {
  std::uint32_t offset;          // the node, or the leaf's first primitive
  std::uint32_t primitiveCount;  // 0 for an inner node
  float entry;
};

int hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

// The subtrees of at most this many primitives are left for the rays to
// build: few enough that a ray builds little it does not need, enough that
// the splits above them are few. On a million triangles, what the build then
// makes at once takes a quarter of the time of the whole tree.
constexpr std::uint32_t kUnbuiltAtMost = 4096;

}  // namespace

Bvh::Bvh(const std::vector<std::unique_ptr<Shape>>& shapes, int threads) {
  std::vector<bool> bounded;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    shapes_.push_back(shapes[i].get());
    bounded.push_back(shapes[i]->bounds().isFinite());
    if (!bounded.back()) unbounded_.push_back(static_cast<int>(i));
  }
  if (threads <= 0) threads = hardwareThreads();
  buildPrimitives_ = primitivesOf(shapes_, bounded, threads);
  primitives_.resize(buildPrimitives_.size());
  const BuiltBvh top = buildBvh(buildPrimitives_, threads, kUnbuiltAtMost);
  const std::vector<WideBvhNode> wideTop = collapseBvh(top.nodes());
  // A subtree of n primitives has fewer than n inner nodes, and so fewer
  // wide nodes, or one, a leaf's, when n is 1.
  nodes_ = std::make_unique_for_overwrite<WideBvhNode[]>(wideTop.size() + primitives_.size());
  std::copy(wideTop.begin(), wideTop.end(), nodes_.get());
  nodeCount_ = static_cast<std::uint32_t>(wideTop.size());
  unbuilt_ = std::vector<UnbuiltChild>(top.unbuilt.size());
  for (std::size_t i = 0; i < unbuilt_.size(); ++i) unbuilt_[i].subtree = top.unbuilt[i];
  for (const BvhNode& node : top.nodes())
    if (node.isLeaf() && node.primitiveCount != kUnbuiltSubtree)
      fillLeafPrimitives(node.offset, node.offset + node.primitiveCount);
}

std::uint32_t Bvh::subtreeRoot(std::uint32_t unbuilt) const {
  UnbuiltChild& child = unbuilt_[unbuilt];
  std::call_once(child.built, [&] {
    child.root = build(child.subtree);
    ++builtCount_;
  });
  return child.root;
}

void Bvh::buildEverySubtree(int threads) const {
  Workers(threads).forEachTask(static_cast<int>(unbuilt_.size()), [&](int unbuilt) {
    subtreeRoot(static_cast<std::uint32_t>(unbuilt));
  });
}

std::uint32_t Bvh::build(const UnbuiltSubtree& subtree) const {
  const BuiltBvh binary = buildSubtree(buildPrimitives_, subtree);
  fillLeafPrimitives(subtree.begin, subtree.end);
  // Its inner nodes' indices depend on where it goes: after the nodes built
  // so far, which other threads may be adding to.
  const std::lock_guard lock(growing_);
  const std::uint32_t root = nodeCount_;
  const std::vector<WideBvhNode> wide = collapseBvh(binary.nodes(), root);
  std::copy(wide.begin(), wide.end(), nodes_.get() + root);
  nodeCount_ = root + static_cast<std::uint32_t>(wide.size());
  return root;
}

void Bvh::fillLeafPrimitives(std::uint32_t begin, std::uint32_t end) const {
  for (std::uint32_t i = begin; i < end; ++i)
    primitives_[i] = leafPrimitive(buildPrimitives_[i].ref());
}

void Bvh::addStats(Stats& stats) const {
  stats.add("bvh_subtrees_deferred", static_cast<double>(unbuilt_.size()));
  stats.add("bvh_subtrees_built", builtCount_.load());
}

Bvh::LeafPrimitive Bvh::leafPrimitive(PrimitiveRef ref) const {
  const Shape& shape = *shapes_[ref.shape];
  const auto index = static_cast<int>(ref.primitive);
  LeafPrimitive primitive{ref, Kind::Other, {}};
  std::array<Vec3, 3> corners{};
  if (shape.primitiveTriangle(index, corners)) {
    primitive.kind = Kind::Triangle;
    primitive.triangle = {corners[0], corners[1] - corners[0], corners[2] - corners[0]};
  } else if (shape.primitiveSphere(index, primitive.sphere.center,
                                   primitive.sphere.radiusSquared)) {
    primitive.kind = Kind::Sphere;
  }
  return primitive;
}

bool Bvh::intersectPrimitive(const LeafPrimitive& primitive, const Ray& ray, float tMin, Hit& hit,
                             IntersectionCounters& counters) const {
  const Shape& shape = *shapes_[primitive.ref.shape];
  const int index = static_cast<int>(primitive.ref.primitive);
  if (primitive.kind == Kind::Other)
    return shape.intersectPrimitive(index, ray, tMin, hit, counters);
  ++counters.tests;
  if (primitive.kind == Kind::Sphere) {
    if (!intersectSphere(ray, primitive.sphere.center, primitive.sphere.radiusSquared, tMin, hit.t,
                         hit.t))
      return false;
  } else {
    const TriangleEdges& triangle = primitive.triangle;
    if (!intersectTriangleEdges(ray, triangle.corner, triangle.edge1, triangle.edge2, tMin, hit.t,
                                hit.t, hit.barycentric))
      return false;
    hit.primitive = index;
  }
  hit.shape = &shape;
  return true;
}

template <typename VisitLeaf>
void Bvh::traverse(const Ray& ray, float tMin, const float& tMax, IntersectionCounters& counters,
                   VisitLeaf&& visitLeaf) const {
  if (primitives_.empty() || !isFinite(ray)) return;
  const BoxRay boxRay(ray);
  std::uint64_t boxesTested = 0;
  PendingChildren<PendingChild> pending;
  PendingChild current{0, 0, tMin};  // the root
  while (true) {
    if (current.primitiveCount > 0) {
      if (current.primitiveCount == kUnbuiltSubtree) {
        current = {subtreeRoot(current.offset), 0, current.entry};
        continue;
      }
      if (!visitLeaf(current.offset, current.primitiveCount)) break;
    } else {
      const WideBvhNode& node = nodes_[current.offset];
      boxesTested += kWideBvhWidth;
      const FourFloats entries = boxRay.entries(node, tMin, tMax);
      const auto childAt = [&](int child) {
        return PendingChild{node.offset[child], node.primitiveCount[child], entries[child]};
      };
      unsigned met = childrenMet(entries);
      // A lone child met is entered at once, as most are near the leaves.
      if (met != 0 && std::has_single_bit(met)) {
        current = childAt(std::countr_zero(met));
        continue;
      }
      pending.openNode();
      for (; met != 0; met &= met - 1) pending.push(childAt(std::countr_zero(met)));
    }
    // The next kept child that a hit found since has not put out of reach.
    if (!pending.takeNext(current, [&](const PendingChild& child) { return child.entry <= tMax; }))
      break;
  }
  counters.nodesVisited += boxesTested;
}

bool Bvh::nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  NearestHit nearest(hit);
  bool found = offerUnbounded(ray, tMin, nearest, counters);
  traverse(ray, tMin, hit.t, counters, [&](std::uint32_t first, std::uint32_t count) {
    found |= offerLeaf(first, count, ray, tMin, nearest, counters);
    return true;
  });
  return found;
}

void Bvh::visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                         IntersectionCounters& counters) const {
  if (!crossUnbounded(ray, tMin, tMax, visitor, counters)) return;
  traverse(ray, tMin, tMax, counters, [&](std::uint32_t first, std::uint32_t count) {
    return crossLeaf(first, count, ray, tMin, tMax, visitor, counters);
  });
}

}  // namespace rise
