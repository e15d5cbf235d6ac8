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
// Large subtrees are built on threads of their own.
#pragma once

#include <cstdint>
#include <vector>

#include "core/bounds.hpp"

namespace rise {

// A primitive of the scene: the index of its shape and its index in the shape.
struct PrimitiveRef {
  std::uint32_t shape;
  std::uint32_t primitive;
};

// One node of the flattened hierarchy, 32 bytes.
struct alignas(32) BvhNode {
  Bounds3 box;
  std::uint32_t offset = 0;          // a leaf's first primitive, an inner node's first child
  std::uint32_t primitiveCount = 0;  // 0 for an inner node

  bool isLeaf() const { return primitiveCount > 0; }
};
static_assert(sizeof(BvhNode) == 32);

// The nodes, two to a 64-byte cache line: the root alone in the first line,
// then each pair of siblings together, so that the two boxes that traversal
// tests at an inner node come in one memory fetch. Node 1, the root's
// partner, is unused; an inner node's children are nodes offset and
// offset + 1, offset even.
class BvhNodeArray {
 public:
  explicit BvhNodeArray(std::size_t slots = 0) : lines_((slots + 1) / 2) {}

  BvhNode& operator[](std::uint32_t index) { return lines_[index / 2].nodes[index % 2]; }
  const BvhNode& operator[](std::uint32_t index) const {
    return lines_[index / 2].nodes[index % 2];
  }
  std::size_t size() const { return 2 * lines_.size(); }  // counting the unused node 1
  bool empty() const { return lines_.empty(); }
  void resize(std::size_t slots) { lines_.resize((slots + 1) / 2); }

 private:
  struct alignas(64) CacheLine {
    BvhNode nodes[2];
  };
  std::vector<CacheLine> lines_;
};

// A primitive as the builder sees it: its box, whose centre (the centroid)
// sorts it into bins.
struct BuildPrimitive {
  Bounds3 box;
  PrimitiveRef ref;

  Vec3 centroid() const { return box.centre(); }
};

// No path from the root to a leaf is longer, so that traversal can keep its
// pending nodes in a fixed array.
inline constexpr int kMaxBvhDepth = 64;

struct BuiltBvh {
  BvhNodeArray nodes;                    // the root first; empty when there were no primitives
  std::vector<PrimitiveRef> primitives;  // in leaf order: a leaf's are contiguous
  int depth = 0;                         // of the deepest leaf, the root being 1
};

// Builds the hierarchy on up to `threads` threads.
BuiltBvh buildBvh(std::vector<BuildPrimitive> primitives, int threads);

}  // namespace rise
