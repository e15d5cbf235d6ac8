#include "ray/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "scene/shapes/triangle.hpp"

namespace rise {
namespace {

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

std::vector<BuildPrimitive> primitivesOf(const std::vector<const Shape*>& shapes,
                                         const std::vector<bool>& bounded, int threads) {
  std::vector<std::size_t> firstOf{0};  // of each shape, among all the primitives
  for (std::size_t shape = 0; shape < shapes.size(); ++shape)
    firstOf.push_back(
        firstOf.back() +
        (bounded[shape] ? static_cast<std::size_t>(shapes[shape]->primitiveCount()) : 0));
  std::vector<BuildPrimitive> primitives(firstOf.back());
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

// Eight floats, for the eight rays of a packet: one AVX register, or two
// of four where the processor has no wider ones. Without AVX, GCC warns that
// passing them changes the calling convention; they never leave this file.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using EightFloats = float __attribute__((vector_size(8 * sizeof(float))));
using EightInts = std::int32_t __attribute__((vector_size(8 * sizeof(std::int32_t))));
static_assert(kPacketSize == 8, "a packet's rays fill one EightFloats");

FourFloats broadcast(float value) { return FourFloats{value, value, value, value}; }
EightFloats broadcastToEight(float value) { return EightFloats{} + value; }

FourFloats fourFloatsAt(const float* first) {
  FourFloats four;
  std::memcpy(&four, first, sizeof four);
  return four;
}

template <typename Floats>
Floats maximum(Floats a, Floats b) {
  return a > b ? a : b;
}
template <typename Floats>
Floats minimum(Floats a, Floats b) {
  return a < b ? a : b;
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
  // inside. The exit is pushed out by a few ulps (T. Ize,
  // "Robust BVH Ray Traversal", JCGT 2(2), 2013), so that rounding never
  // loses a box the ray grazes. Always inlined: called apart, it would pass
  // its result through memory.
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
  static constexpr float kRobustExit = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();

  Vec3 origin_;
  Vec3 inverseDirection_;
  glm::bvec3 entersByMax_;
};

// The rays of a packet made ready for box tests, lane by lane as BoxRay
// makes one ray: the same arithmetic, so that each lane finds the same
// entries as its ray alone would. Here the eight rays test one box at once,
// where BoxRay's one ray tests four.
class BoxPacket {
 public:
  explicit BoxPacket(const RayPacket& packet) {
    for (int lane = 0; lane < kPacketSize; ++lane) {
      // Lanes past the packet's rays repeat its first; no child is entered for them.
      const Ray& ray = packet.rays[lane < packet.size ? lane : 0];
      for (int axis = 0; axis < 3; ++axis) {
        origin_[axis][lane] = ray.origin[axis];
        inverseDirection_[axis][lane] = 1.0f / ray.direction[axis];
        entersByMax_[axis][lane] = inverseDirection_[axis][lane] < 0.0f ? -1 : 0;
      }
    }
  }

  // Where each lane's ray enters the child's box within (tMin, its tMax), or
  // infinity where it misses it there.
  [[gnu::always_inline]] EightFloats entries(const WideBvhNode& node, int child, float tMin,
                                             EightFloats tMax) const {
    EightFloats enter = broadcastToEight(tMin);
    EightFloats exit = broadcastToEight(kInfinity);
    for (int axis = 0; axis < 3; ++axis) {
      const EightFloats lower = broadcastToEight(node.lower[axis][child]);
      const EightFloats upper = broadcastToEight(node.upper[axis][child]);
      const EightFloats nearFaces = entersByMax_[axis] != 0 ? upper : lower;
      const EightFloats farFaces = entersByMax_[axis] != 0 ? lower : upper;
      enter = maximum((nearFaces - origin_[axis]) * inverseDirection_[axis], enter);
      exit = minimum((farFaces - origin_[axis]) * inverseDirection_[axis], exit);
    }
    return enter <= minimum(exit * kRobustExit, tMax) ? enter : broadcastToEight(kInfinity);
  }

 private:
  static constexpr float kRobustExit = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();

  EightFloats origin_[3];
  EightFloats inverseDirection_[3];
  EightInts entersByMax_[3];
};

// The lanes whose entries are finite, the rays that meet a box.
unsigned lanesMet(EightFloats entries) {
  const EightInts met = entries != broadcastToEight(kInfinity);
#if defined(__AVX__)
  return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(met)));
#else
  unsigned lanes = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) lanes |= (met[lane] != 0 ? 1u : 0u) << lane;
  return lanes;
#endif
}

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

// Each inner node visited keeps up to three of its children.
constexpr int kMaxPendingChildren = (kWideBvhWidth - 1) * kMaxBvhDepth + 1;

// The children a traversal has yet to enter (Child: a PendingChild, or a
// packet's). Each node opened pushes the children it meets, ordered among
// themselves by insertion, the nearest on top, to be entered next.
template <typename Child>
class PendingChildren {
 public:
  // The children of the node being opened begin here.
  void openNode() { firstOfNode_ = count_; }

  void push(const Child& child) {
    int slot = count_++;
    for (; slot > firstOfNode_ && children_[slot - 1].entry < child.entry; --slot)
      children_[slot] = children_[slot - 1];
    children_[slot] = child;
  }

  // Takes the top child still in reach (`inReach(child)`) into `next`,
  // dropping those above it that are not; false when none is left.
  template <typename InReach>
  bool takeNext(Child& next, InReach&& inReach) {
    while (count_ > 0 && !inReach(children_[count_ - 1])) --count_;
    if (count_ == 0) return false;
    next = children_[--count_];
    return true;
  }

 private:
  Child children_[kMaxPendingChildren];
  int count_ = 0;
  int firstOfNode_ = 0;
};

int hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace

Bvh::Bvh(const std::vector<std::unique_ptr<Shape>>& shapes, int threads) {
  std::vector<bool> bounded;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    shapes_.push_back(shapes[i].get());
    bounded.push_back(shapes[i]->bounds().isFinite());
    if (!bounded.back()) unbounded_.push_back(static_cast<int>(i));
  }
  if (threads <= 0) threads = hardwareThreads();
  const BuiltBvh built = buildBvh(primitivesOf(shapes_, bounded, threads), threads);
  nodes_ = collapseBvh(built.nodes());
  primitives_.resize(built.primitives.size());
  inShares(primitives_.size(), threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const PrimitiveRef ref = built.primitives[i].ref();
      std::array<Vec3, 3> corners{};
      const bool isTriangle =
          shapes_[ref.shape]->primitiveTriangle(static_cast<int>(ref.primitive), corners);
      primitives_[i] = {ref, isTriangle, corners[0], corners[1] - corners[0],
                        corners[2] - corners[0]};
    }
  });
}

bool Bvh::intersectPrimitive(const LeafPrimitive& primitive, const Ray& ray, float tMin, Hit& hit,
                             IntersectionCounters& counters) const {
  const Shape& shape = *shapes_[primitive.ref.shape];
  const int index = static_cast<int>(primitive.ref.primitive);
  if (!primitive.isTriangle) return shape.intersectPrimitive(index, ray, tMin, hit, counters);
  ++counters.tests;
  if (!intersectTriangleEdges(ray, primitive.corner, primitive.edge1, primitive.edge2, tMin, hit.t,
                              hit.t, hit.barycentric))
    return false;
  hit.shape = &shape;
  hit.primitive = index;
  return true;
}

template <typename VisitLeaf>
void Bvh::traverse(const Ray& ray, float tMin, const float& tMax, IntersectionCounters& counters,
                   VisitLeaf&& visitLeaf) const {
  if (nodes_.empty() || !isFinite(ray)) return;
  const BoxRay boxRay(ray);
  std::uint64_t boxesTested = 0;
  PendingChildren<PendingChild> pending;
  PendingChild current{0, 0, tMin};  // the root
  while (true) {
    if (current.primitiveCount > 0) {
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

namespace {

// The next float above t: std::nextafter(t, infinity), without a call into
// the math library for the positive distances that hits have, nor for the
// infinity of a ray that has hit nothing yet.
float nextAbove(float t) {
  if (t > 0.0f && t < kInfinity) return std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) + 1);
  if (t == kInfinity) return t;
  return std::nextafter(t, kInfinity);
}

}  // namespace

// A ray through the edge that two triangles share meets both at the same t.
// Brute force keeps the first it tests, the first in the scene's order; so
// does the BVH, whatever order it tests them in, so that every structure
// gives the same hit.
class NearestHit {
 public:
  NearestHit() = default;  // to be given its hit
  explicit NearestHit(Hit& hit) : hit_(&hit) {}

  // Offers the hit of one primitive, found by `intersect(candidate)`.
  template <typename Intersect>
  bool offer(PrimitiveRef ref, Intersect&& intersect) {
    Hit candidate = *hit_;
    candidate.t = nextAbove(hit_->t);  // an equal t too
    if (!intersect(candidate)) return false;
    if (candidate.t == hit_->t && !(found_ && comesBefore(ref, ref_))) return false;
    *hit_ = candidate;
    ref_ = ref;
    found_ = true;
    return true;
  }

 private:
  static bool comesBefore(PrimitiveRef a, PrimitiveRef b) {
    return a.shape < b.shape || (a.shape == b.shape && a.primitive < b.primitive);
  }

  Hit* hit_ = nullptr;
  PrimitiveRef ref_{0, 0};
  bool found_ = false;
};

inline bool Bvh::offerUnbounded(const Ray& ray, float tMin, NearestHit& nearest,
                                IntersectionCounters& counters) const {
  bool found = false;
  for (int shape : unbounded_) {
    found |= nearest.offer({static_cast<std::uint32_t>(shape), 0}, [&](Hit& candidate) {
      return shapes_[shape]->intersect(ray, tMin, candidate, counters);
    });
  }
  return found;
}

inline bool Bvh::offerLeaf(std::uint32_t first, std::uint32_t count, const Ray& ray, float tMin,
                           NearestHit& nearest, IntersectionCounters& counters) const {
  bool found = false;
  for (std::uint32_t i = first; i < first + count; ++i) {
    found |= nearest.offer(primitives_[i].ref, [&](Hit& candidate) {
      return intersectPrimitive(primitives_[i], ray, tMin, candidate, counters);
    });
  }
  return found;
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

namespace {

// A child that a packet's traversal has yet to enter, and the lanes whose
// rays meet it, the nearest at `entry`.
struct PendingPacketChild {
  std::uint32_t offset;          // the node, or the leaf's first primitive
  std::uint32_t primitiveCount;  // 0 for an inner node
  unsigned lanes;
  float entry;
};

// The nearest of eight entries.
float nearestEntry(EightFloats entries) {
  float nearest = entries[0];
  for (int lane = 1; lane < kPacketSize; ++lane) nearest = std::min(nearest, entries[lane]);
  return nearest;
}

// All ones in the lanes of `lanes`' bits, zero in the others.
EightInts laneMask(unsigned lanes) {
  const EightInts bits{1, 2, 4, 8, 16, 32, 64, 128};
  return (bits & static_cast<std::int32_t>(lanes)) != 0;
}

// Whether a kept child is still in reach of one of its rays: the nearest
// hit of one of them is beyond the child's nearest entry.
bool anyReaches(const PendingPacketChild& child, EightFloats tMax) {
  for (unsigned lanes = child.lanes; lanes != 0; lanes &= lanes - 1)
    if (child.entry <= tMax[std::countr_zero(lanes)]) return true;
  return false;
}

}  // namespace

// The packet goes down the tree as one ray does, nearest child first, into
// every child that any of its rays meets; a child keeps the lanes of the
// rays that meet it, and only those test its children and its primitives.
// Each ray keeps its own nearest hit, so that it finds the same as alone.
void Bvh::nearestOfPacket(RayPacket& packet, float tMin) const {
  std::array<NearestHit, kPacketSize> nearest;
  unsigned traversing = 0;
  EightFloats tMax = broadcastToEight(kInfinity);
  for (int lane = 0; lane < packet.size; ++lane) {
    nearest[lane] = NearestHit(packet.hits[lane]);
    packet.found[lane] = offerUnbounded(packet.rays[lane], tMin, nearest[lane], packet.costs[lane]);
    tMax[lane] = packet.hits[lane].t;
    if (!nodes_.empty() && isFinite(packet.rays[lane])) traversing |= 1u << lane;
  }
  if (traversing == 0) return;
  const BoxPacket boxes(packet);
  EightInts boxesTested{};
  PendingChildren<PendingPacketChild> pending;
  PendingPacketChild current{0, 0, traversing, tMin};  // the root
  while (true) {
    if (current.primitiveCount > 0) {
      for (unsigned lanes = current.lanes; lanes != 0; lanes &= lanes - 1) {
        const int lane = std::countr_zero(lanes);
        packet.found[lane] |= offerLeaf(current.offset, current.primitiveCount, packet.rays[lane],
                                        tMin, nearest[lane], packet.costs[lane]);
        tMax[lane] = packet.hits[lane].t;
      }
    } else {
      const WideBvhNode& node = nodes_[current.offset];
      // The lanes not in this child reach no box.
      const EightInts active = laneMask(current.lanes);
      boxesTested += active & kWideBvhWidth;
      const EightFloats reach = active != 0 ? tMax : broadcastToEight(-kInfinity);
      pending.openNode();
      for (int child = 0; child < kWideBvhWidth; ++child) {
        const EightFloats entries = boxes.entries(node, child, tMin, reach);
        const unsigned lanes = lanesMet(entries);
        if (lanes != 0)
          pending.push(
              {node.offset[child], node.primitiveCount[child], lanes, nearestEntry(entries)});
      }
    }
    // The next kept child that some of its rays' hits since leave in reach.
    if (!pending.takeNext(current,
                          [&](const PendingPacketChild& child) { return anyReaches(child, tMax); }))
      break;
  }
  for (int lane = 0; lane < packet.size; ++lane)
    packet.costs[lane].nodesVisited += static_cast<std::uint64_t>(boxesTested[lane]);
}

void Bvh::visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                         IntersectionCounters& counters) const {
  for (int shape : unbounded_)
    if (crosses(*shapes_[shape], ray, tMin, tMax, counters) && !visitor.crossed(shape)) return;
  traverse(ray, tMin, tMax, counters, [&](std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t i = first; i < first + count; ++i) {
      Hit crossing;
      crossing.t = tMax;
      if (intersectPrimitive(primitives_[i], ray, tMin, crossing, counters) &&
          !visitor.crossed(static_cast<int>(primitives_[i].ref.shape)))
        return false;
    }
    return true;
  });
}

}  // namespace rise
