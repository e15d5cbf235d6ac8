// A binary bounding volume hierarchy collapsed into one of four children a
// node (H. Dammertz, J. Hanika and A. Keller, "Shallow Bounding Volume
// Hierarchies for Fast SIMD Ray Tracing of Incoherent Rays", EGSR 2008;
// I. Wald, C. Benthin and S. Boulos, "Getting Rid of Packets", IEEE
// Symposium on Interactive Ray Tracing, 2008).
//
// A ray at a binary node tests two boxes, one after the other. A processor
// can compare four numbers in one instruction as fast as one, so a node of
// four children lets one ray test four boxes at once, and the tree is half
// as deep. The builder's surface area heuristic still chooses every split:
// collapsing only regroups its binary tree, opening an inner child of a node
// into its own two children, the largest child first, until the node has
// four (or only leaves).
//
// A node stores its children's boxes axis by axis (all four lower x, then
// all four lower y, ...), the layout in which the four slab tests of an axis
// are one vector operation.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ray/bvh_builder.hpp"

namespace rise {

inline constexpr int kWideBvhWidth = 4;

struct alignas(64) WideBvhNode {
  // lower[axis][child], upper[axis][child]. A slot without a child holds an
  // empty box (lower +infinity, upper -infinity), which no ray enters.
  float lower[3][kWideBvhWidth];
  float upper[3][kWideBvhWidth];
  // An inner child's node, or a leaf child's first primitive, or the index
  // of an unbuilt child among the builder's unbuilt subtrees.
  std::uint32_t offset[kWideBvhWidth];
  // A leaf child's number of primitives; 0 for an inner child or an empty
  // slot; kUnbuiltSubtree for a child not built yet.
  std::uint32_t primitiveCount[kWideBvhWidth];

  int childCount() const;
  Bounds3 childBox(int child) const;
};
static_assert(sizeof(WideBvhNode) == 128, "two cache lines");

// The four-wide tree of a binary one, its root first: a binary tree that is a
// single leaf becomes a root with one child. Empty when `binary` is. Its
// inner children's indices count from `firstIndex`, where its root will be.
// An unbuilt subtree stays one, a child as a leaf is.
std::vector<WideBvhNode> collapseBvh(std::span<const BvhNode> binary, std::uint32_t firstIndex = 0);

}  // namespace rise
