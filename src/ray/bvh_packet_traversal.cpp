// A packet's traversal of the BVH (I. Wald, P. Slusallek, C. Benthin and
// M. Wagner, "Interactive Rendering with Coherent Ray Tracing", Computer
// Graphics Forum 20(3), 2001): the primary rays of neighbouring pixels are
// nearly parallel and meet nearly the same boxes, so eight of them go down
// the tree together, loading each node once for all eight and testing one
// child's box against the eight rays at once. The packet enters every child
// that any of its rays meets, nearest first, and a child keeps the lanes of
// the rays that meet it: only those test its children and its primitives.
// Each ray keeps its own nearest hit, so that it finds what it would alone.
// Shadow rays from neighbouring points towards one light are as coherent:
// they go down together the same way, each telling its own visitor of the
// shapes it crosses, and each leaving the packet when its visitor stops it.
// They take the children in the order they come, not nearest first: any
// crossing will do, and a light's unshadowed rays visit every box on their
// way whatever the order.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "ray/bvh_traversal.hpp"

namespace rise {
namespace {

using namespace bvh_traversal;

// Eight floats, for the eight rays of a packet: one AVX register, or two
// of four where the processor has no wider ones. Without AVX, GCC warns that
// passing them changes the calling convention; they never leave this file.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using EightFloats = float __attribute__((vector_size(8 * sizeof(float))));
using EightInts = std::int32_t __attribute__((vector_size(8 * sizeof(std::int32_t))));
static_assert(kPacketSize == 8, "a packet's rays fill one EightFloats");

EightFloats broadcastToEight(float value) { return EightFloats{} + value; }

// The rays of a packet made ready for box tests, lane by lane as BoxRay
// (bvh.cpp) makes one ray: the same arithmetic, so that each lane finds the same
// entries as its ray alone would. Here the eight rays test one box at once,
// where BoxRay's one ray tests four.
class BoxPacket {
 public:
  // The first `size` of `rays`.
  BoxPacket(const std::array<Ray, kPacketSize>& rays, int size) {
    for (int lane = 0; lane < kPacketSize; ++lane) {
      // Lanes past the packet's rays repeat its first; no child is entered for them.
      const Ray& ray = rays[lane < size ? lane : 0];
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

// Asks for the first two cache lines at `memory`: a kept child's, a node or
// a leaf's first primitives, before it is entered. A large scene's tree is
// far larger than the caches, and a packet's rays spend long enough on each
// node for the next to arrive meanwhile: on a million triangles, the
// hybrid's render without the BVH's build took about a twentieth less. (One
// ray's traversal, which spends little on each node, gained nothing.)
void prefetchTwoLines(const void* memory) {
  const char* const bytes = static_cast<const char*>(memory);
  __builtin_prefetch(bytes);
  __builtin_prefetch(bytes + 64);
}

// The packet goes down the tree as one ray does, nearest child first where
// `kNearestFirst`, into every child that any of its rays meets; a child keeps
// the lanes of the rays that meet it, and only those test its children and
// its primitives.
// `tMax` holds each lane's reach, which visitLeaf(first primitive, count,
// lane) may shrink as the lane's ray finds hits, or end by setting it below
// tMin; lanes past `traversing` reach no box. Each lane's boxes tested are
// added to its cost.
template <bool kNearestFirst, typename VisitLeaf>
void walkPacket(const Bvh& bvh, const BoxPacket& boxes, unsigned traversing, float tMin,
                EightFloats& tMax, std::array<IntersectionCounters, kPacketSize>& costs,
                VisitLeaf&& visitLeaf) {
  // Where the nodes are, the built and those still to be: the count of
  // nodes() grows as subtrees are built.
  const WideBvhNode* const nodes = bvh.nodes().data();
  const std::span<const Bvh::LeafPrimitive> primitives = bvh.primitives();
  EightInts boxesTested{};
  PendingChildren<PendingPacketChild> pending;
  PendingPacketChild current{0, 0, traversing, tMin};  // the root
  while (true) {
    if (current.primitiveCount > 0) {
      if (current.primitiveCount == kUnbuiltSubtree) {
        current.offset = bvh.subtreeRoot(current.offset);
        current.primitiveCount = 0;
        continue;
      }
      for (unsigned lanes = current.lanes; lanes != 0; lanes &= lanes - 1) {
        const int lane = std::countr_zero(lanes);
        if (tMax[lane] >= tMin)
          tMax[lane] = visitLeaf(current.offset, current.primitiveCount, lane);
      }
    } else {
      const WideBvhNode& node = nodes[current.offset];
      // The lanes not in this child reach no box.
      const EightInts active = laneMask(current.lanes);
      boxesTested += active & kWideBvhWidth;
      const EightFloats reach = active != 0 ? tMax : broadcastToEight(-kInfinity);
      pending.openNode();
      for (int child = 0; child < kWideBvhWidth; ++child) {
        const EightFloats entries = boxes.entries(node, child, tMin, reach);
        const unsigned lanes = lanesMet(entries);
        if (lanes == 0) continue;
        const std::uint32_t offset = node.offset[child];
        // An unbuilt child's offset is a subtree's index: its prefetch only
        // misses.
        prefetchTwoLines(node.primitiveCount[child] == 0
                             ? static_cast<const void*>(&nodes[offset])
                             : static_cast<const void*>(&primitives[offset]));
        pending.push({offset, node.primitiveCount[child], lanes,
                      kNearestFirst ? nearestEntry(entries) : tMin});
      }
    }
    // The next kept child that some of its rays' hits since leave in reach.
    if (!pending.takeNext(current,
                          [&](const PendingPacketChild& child) { return anyReaches(child, tMax); }))
      break;
  }
  for (int lane = 0; lane < kPacketSize; ++lane)
    costs[lane].nodesVisited += static_cast<std::uint64_t>(boxesTested[lane]);
}

}  // namespace

// Each ray keeps its own nearest hit, so that it finds the same as alone.
void Bvh::nearestOfPacket(RayPacket& packet, float tMin) const {
  std::array<NearestHit, kPacketSize> nearest;
  unsigned traversing = 0;
  EightFloats tMax = broadcastToEight(kInfinity);
  for (int lane = 0; lane < packet.size; ++lane) {
    nearest[lane] = NearestHit(packet.hits[lane]);
    packet.found[lane] = offerUnbounded(packet.rays[lane], tMin, nearest[lane], packet.costs[lane]);
    tMax[lane] = packet.hits[lane].t;
    if (!primitives_.empty() && isFinite(packet.rays[lane])) traversing |= 1u << lane;
  }
  if (traversing == 0) return;
  walkPacket<true>(*this, BoxPacket(packet.rays, packet.size), traversing, tMin, tMax, packet.costs,
                   [&](std::uint32_t first, std::uint32_t count, int lane) {
                     packet.found[lane] |= offerLeaf(first, count, packet.rays[lane], tMin,
                                                     nearest[lane], packet.costs[lane]);
                     return packet.hits[lane].t;
                   });
}

// A ray whose visitor asks to stop leaves the packet. Without eight-wide
// vectors, a packet's two halves of four cost more than its rays one at a
// time (measured on shadow rays, which part in the leaves): those builds
// trace them so.
#if defined(__AVX__)
void Bvh::visitCrossingsOfPacket(ShadowRayPacket& packet, float tMin,
                                 const std::array<CrossingVisitor*, kPacketSize>& visitors) const {
  unsigned traversing = 0;
  EightFloats tMax = broadcastToEight(-kInfinity);
  for (int lane = 0; lane < packet.size; ++lane) {
    const Ray& ray = packet.rays[lane];
    if (!crossUnbounded(ray, tMin, packet.tMax[lane], *visitors[lane], packet.costs[lane]))
      continue;
    tMax[lane] = packet.tMax[lane];
    if (!primitives_.empty() && isFinite(ray)) traversing |= 1u << lane;
  }
  if (traversing == 0) return;
  walkPacket<false>(*this, BoxPacket(packet.rays, packet.size), traversing, tMin, tMax,
                    packet.costs, [&](std::uint32_t first, std::uint32_t count, int lane) {
                      const bool goesOn =
                          crossLeaf(first, count, packet.rays[lane], tMin, packet.tMax[lane],
                                    *visitors[lane], packet.costs[lane]);
                      return goesOn ? packet.tMax[lane] : -kInfinity;
                    });
}
#else
void Bvh::visitCrossingsOfPacket(ShadowRayPacket& packet, float tMin,
                                 const std::array<CrossingVisitor*, kPacketSize>& visitors) const {
  Accelerator::visitCrossingsOfPacket(packet, tMin, visitors);
}
#endif

}  // namespace rise
