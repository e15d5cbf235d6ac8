// Building a bounding volume hierarchy top-down by the surface area
// heuristic (J. Goldsmith and J. Salmon, "Automatic Creation of Object
// Hierarchies for Ray Tracing", IEEE CG&A 7(5), 1987; J. D. MacDonald and
// K. S. Booth, "Heuristics for ray tracing using space subdivision", The
// Visual Computer 6(3), 1990).
//
// A ray that passes through a box hits a box inside it with a probability of
// about the ratio of their surface areas. So the expected cost of splitting a
// node's primitives into a left and a right group is
//
//   traversal + (area(left) * count(left) + area(right) * count(right)) / area(node)
//
// primitive tests, against count(node) for keeping them all in a leaf. The
// candidate splits are planes between bins: the primitives' centroids are
// sorted into equal slices of the node along each axis, and only the planes
// between slices are tried (I. Wald, "On fast Construction of SAH-based
// Bounding Volume Hierarchies", IEEE Symposium on Interactive Ray Tracing,
// 2007), which makes each level one pass over its primitives.
//
// Large nodes are binned by all the threads at once, each binning a share
// of the primitives; large subtrees are built on threads of their own.
//
// A subtree may also be left unbuilt, its primitives only gathered in a run
// of their own, for whoever needs it first to build (bvh.hpp): the splits
// above it, and so its primitives, are the same whenever it is built, and
// so is the subtree.
#pragma once

#include <bit>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/bounds.hpp"

namespace rise {

// A primitive of the scene: the index of its shape and its index in the shape.
struct PrimitiveRef {
  std::uint32_t shape;
  std::uint32_t primitive;
};

// The primitive count of a node whose subtree was left unbuilt; its offset
// indexes BuiltBvh::unbuilt.
inline constexpr std::uint32_t kUnbuiltSubtree = 0xffffffff;

// One node of the binary hierarchy: an inner node's children are the nodes
// offset and offset + 1.
struct BvhNode {
  Bounds3 box;
  std::uint32_t offset;          // a leaf's first primitive, an inner node's first child
  std::uint32_t primitiveCount;  // 0 for an inner node

  // A leaf, or a subtree left unbuilt: a node whose children are not here.
  bool isLeaf() const { return primitiveCount > 0; }
};

// A primitive as the builder sees it: its box, whose centre (the centroid)
// sorts it into bins. The box's corners are two rows of four floats, which
// SIMD instructions load whole; the fourth float of each row holds the bits
// of half of the reference.
struct alignas(16) BuildPrimitive {
  BuildPrimitive() = default;
  BuildPrimitive(const Bounds3& box, PrimitiveRef ref)
      : lower{box.min.x, box.min.y, box.min.z, std::bit_cast<float>(ref.shape)},
        upper{box.max.x, box.max.y, box.max.z, std::bit_cast<float>(ref.primitive)} {}

  Bounds3 box() const {
    return {Vec3(lower[0], lower[1], lower[2]), Vec3(upper[0], upper[1], upper[2])};
  }
  PrimitiveRef ref() const {
    return {std::bit_cast<std::uint32_t>(lower[3]), std::bit_cast<std::uint32_t>(upper[3])};
  }

  alignas(16) float lower[4];
  alignas(16) float upper[4];
};

// No path from the root to a leaf is longer, so that traversal can keep its
// pending nodes in a fixed array.
inline constexpr int kMaxBvhDepth = 64;

// The primitives [begin, end), sorted into a run of their own by the splits
// above them, whose subtree is `depth` nodes below the root.
struct UnbuiltSubtree {
  std::uint32_t begin;
  std::uint32_t end;
  int depth;
};

struct BuiltBvh {
  // The root first; none when there were no primitives. Left uninitialised
  // when allocated, so that the threads that fill them bring in their pages.
  std::unique_ptr<BvhNode[]> nodeStorage;
  std::size_t nodeCount = 0;
  std::vector<UnbuiltSubtree> unbuilt;  // the subtrees left unbuilt, in no order

  std::span<const BvhNode> nodes() const { return {nodeStorage.get(), nodeCount}; }
};

// Builds the hierarchy of `primitives` on up to `threads` threads, ordering
// them so that a leaf's are contiguous. When there are more than
// `unbuiltAtMost`, the subtrees of at most that many are left unbuilt: a
// smaller tree is built whole, for a root over subtrees left unbuilt would
// be a level more for every ray, where the four-wide root would have held
// their children.
BuiltBvh buildBvh(std::span<BuildPrimitive> primitives, int threads,
                  std::uint32_t unbuiltAtMost = 0);

// Builds, on the calling thread, a subtree that buildBvh left unbuilt, of
// the same primitives; its nodes' indices count from its root, 0.
BuiltBvh buildSubtree(std::span<BuildPrimitive> primitives, const UnbuiltSubtree& subtree);

}  // namespace rise
