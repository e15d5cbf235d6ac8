#include "ray/wide_bvh.hpp"

#include <algorithm>
#include <array>

namespace rise {
namespace {

WideBvhNode emptyNode() {
  WideBvhNode node{};
  for (int axis = 0; axis < 3; ++axis) {
    std::fill(std::begin(node.lower[axis]), std::end(node.lower[axis]), kInfinity);
    std::fill(std::begin(node.upper[axis]), std::end(node.upper[axis]), -kInfinity);
  }
  return node;
}

void setChildBox(WideBvhNode& node, int child, const Bounds3& box) {
  for (int axis = 0; axis < 3; ++axis) {
    node.lower[axis][child] = box.min[axis];
    node.upper[axis][child] = box.max[axis];
  }
}

class Collapser {
 public:
  Collapser(std::span<const BvhNode> binary, std::uint32_t firstIndex)
      : binary_(binary), firstIndex_(firstIndex) {
    // No more wide nodes than binary inner nodes: the vector never moves
    // (pages reserved but not filled cost nothing).
    wide_.reserve(binary.size() / 2 + 1);
  }

  std::vector<WideBvhNode> run() {
    if (binary_.empty()) return {};
    if (binary_[0].isLeaf()) {
      addNode({{0}, 1});
    } else {
      collapse(0);
    }
    return std::move(wide_);
  }

 private:
  // Makes the wide node of the binary inner node `inner`; returns its index.
  std::uint32_t collapse(std::uint32_t inner) { return addNode(descendantsToKeep(inner)); }

  // Up to four binary nodes, the children of a wide one.
  struct Children {
    std::array<std::uint32_t, kWideBvhWidth> nodes;
    std::size_t count;

    std::uint32_t* begin() { return nodes.data(); }
    std::uint32_t* end() { return nodes.data() + count; }
    std::size_t size() const { return count; }
    std::uint32_t operator[](std::size_t slot) const { return nodes[slot]; }
  };

  // The children of the binary inner node, with the inner ones among them
  // opened into theirs, the largest first, while there is room for both.
  Children descendantsToKeep(std::uint32_t inner) const {
    Children kept{{binary_[inner].offset, binary_[inner].offset + 1}, 2};
    while (kept.size() < kWideBvhWidth) {
      auto largest = kept.end();
      for (auto child = kept.begin(); child != kept.end(); ++child) {
        if (binary_[*child].isLeaf()) continue;
        if (largest == kept.end() ||
            binary_[*child].box.surfaceArea() > binary_[*largest].box.surfaceArea())
          largest = child;
      }
      if (largest == kept.end()) break;
      const std::uint32_t firstGrandchild = binary_[*largest].offset;
      *largest = firstGrandchild;
      kept.nodes[kept.count++] = firstGrandchild + 1;
    }
    return kept;
  }

  std::uint32_t addNode(const Children& children) {
    const auto index = static_cast<std::uint32_t>(wide_.size());
    wide_.push_back(emptyNode());
    for (std::size_t slot = 0; slot < children.size(); ++slot) {
      const BvhNode& child = binary_[children[slot]];
      const int lane = static_cast<int>(slot);
      // The node is reached again by its index: collapsing the children
      // below grows wide_ and may move it.
      setChildBox(wide_[index], lane, child.box);
      wide_[index].primitiveCount[lane] = child.primitiveCount;
      const std::uint32_t offset =
          child.isLeaf() ? child.offset : firstIndex_ + collapse(children[slot]);
      wide_[index].offset[lane] = offset;
    }
    return index;
  }

  std::span<const BvhNode> binary_;
  const std::uint32_t firstIndex_;
  std::vector<WideBvhNode> wide_;
};

}  // namespace

int WideBvhNode::childCount() const {
  int count = 0;
  for (int child = 0; child < kWideBvhWidth; ++child)
    if (!childBox(child).isEmpty()) ++count;
  return count;
}

Bounds3 WideBvhNode::childBox(int child) const {
  Bounds3 box;
  for (int axis = 0; axis < 3; ++axis) {
    box.min[axis] = lower[axis][child];
    box.max[axis] = upper[axis][child];
  }
  return box;
}

std::vector<WideBvhNode> collapseBvh(std::span<const BvhNode> binary, std::uint32_t firstIndex) {
  return Collapser(binary, firstIndex).run();
}

}  // namespace rise
