#include "ray/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "scene/shapes/triangle.hpp"

namespace rise {
namespace {

// Every primitive's box is widened by this fraction of its distance from the
// origin, so that a hit the primitive's own test finds on its very edge is
// never outside its box through rounding.
constexpr float kBoxAllowance = 1e-6f;

Bounds3 widened(const Bounds3& box) {
  const Vec3 allowance = kBoxAllowance * glm::max(glm::abs(box.min), glm::abs(box.max));
  return {box.min - allowance, box.max + allowance};
}

std::vector<BuildPrimitive> primitivesOf(const std::vector<const Shape*>& shapes,
                                         const std::vector<bool>& bounded) {
  std::size_t count = 0;
  for (std::size_t shape = 0; shape < shapes.size(); ++shape)
    if (bounded[shape]) count += static_cast<std::size_t>(shapes[shape]->primitiveCount());
  std::vector<BuildPrimitive> primitives;
  primitives.reserve(count);
  for (std::size_t shape = 0; shape < shapes.size(); ++shape) {
    if (!bounded[shape]) continue;
    for (int primitive = 0; primitive < shapes[shape]->primitiveCount(); ++primitive) {
      primitives.push_back(
          {widened(shapes[shape]->primitiveBounds(primitive)),
           {static_cast<std::uint32_t>(shape), static_cast<std::uint32_t>(primitive)}});
    }
  }
  return primitives;
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

  // Where the ray enters `box` within (tMin, tMax), or infinity if it misses
  // it there. A direction component of zero makes an infinite inverse; for
  // an origin on the box's face that gives 0 * infinity = NaN, which the
  // comparisons below drop (std::max(a, NaN) is a), so that the ray lying in
  // the face counts as inside. The exit is pushed out by a few ulps (T. Ize,
  // "Robust BVH Ray Traversal", JCGT 2(2), 2013), so that rounding never
  // loses a box the ray grazes.
  float entry(const Bounds3& box, float tMin, float tMax) const {
    float enter = tMin;
    float exit = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
      const float nearFace = entersByMax_[axis] ? box.max[axis] : box.min[axis];
      const float farFace = entersByMax_[axis] ? box.min[axis] : box.max[axis];
      enter = std::max(enter, (nearFace - origin_[axis]) * inverseDirection_[axis]);
      exit = std::min(exit, (farFace - origin_[axis]) * inverseDirection_[axis]);
    }
    return enter <= std::min(exit * kRobustExit, tMax) ? enter : kInfinity;
  }

 private:
  static constexpr float kRobustExit = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();

  Vec3 origin_;
  Vec3 inverseDirection_;
  glm::bvec3 entersByMax_;
};

struct PendingNode {
  std::uint32_t node;
  float entry;
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
  BuiltBvh built =
      buildBvh(primitivesOf(shapes_, bounded), threads > 0 ? threads : hardwareThreads());
  nodes_ = std::move(built.nodes);
  depth_ = built.depth;
  primitives_.reserve(built.primitives.size());
  for (const PrimitiveRef& ref : built.primitives) {
    LeafPrimitive& primitive = primitives_.emplace_back(LeafPrimitive{ref, false, {}});
    primitive.isTriangle =
        shapes_[ref.shape]->primitiveTriangle(static_cast<int>(ref.primitive), primitive.corners);
  }
}

bool Bvh::intersectPrimitive(const LeafPrimitive& primitive, const Ray& ray, float tMin, Hit& hit,
                             IntersectionCounters& counters) const {
  const Shape& shape = *shapes_[primitive.ref.shape];
  const int index = static_cast<int>(primitive.ref.primitive);
  if (!primitive.isTriangle) return shape.intersectPrimitive(index, ray, tMin, hit, counters);
  ++counters.tests;
  const auto& [v0, v1, v2] = primitive.corners;
  if (!intersectTriangle(ray, v0, v1, v2, tMin, hit.t, hit.t, hit.barycentric)) return false;
  hit.shape = &shape;
  hit.primitive = index;
  return true;
}

template <typename VisitLeaf>
void Bvh::traverse(const Ray& ray, float tMin, const float& tMax, IntersectionCounters& counters,
                   VisitLeaf&& visitLeaf) const {
  if (nodes_.empty()) return;
  const BoxRay boxRay(ray);
  std::uint64_t boxesTested = 1;
  if (boxRay.entry(nodes_[0].box, tMin, tMax) == kInfinity) {
    counters.nodesVisited += boxesTested;
    return;
  }

  PendingNode pending[kMaxBvhDepth];
  int pendingCount = 0;
  std::uint32_t current = 0;
  while (true) {
    const BvhNode& node = nodes_[current];
    if (node.isLeaf()) {
      if (!visitLeaf(node)) break;
    } else {
      boxesTested += 2;
      const std::uint32_t first = node.offset;
      const float firstEntry = boxRay.entry(nodes_[first].box, tMin, tMax);
      const float secondEntry = boxRay.entry(nodes_[first + 1].box, tMin, tMax);
      // Siblings are an even index and the next: index ^ 1 is the sibling.
      const std::uint32_t near = secondEntry < firstEntry ? first + 1 : first;
      const float nearEntry = std::min(firstEntry, secondEntry);
      const float farEntry = std::max(firstEntry, secondEntry);
      if (farEntry != kInfinity) pending[pendingCount++] = {near ^ 1u, farEntry};
      if (nearEntry != kInfinity) {
        current = near;
        continue;
      }
    }
    // The next kept box that a hit found since has not put out of reach.
    while (pendingCount > 0 && pending[pendingCount - 1].entry > tMax) --pendingCount;
    if (pendingCount == 0) break;
    current = pending[--pendingCount].node;
  }
  counters.nodesVisited += boxesTested;
}

// A ray through the edge that two triangles share meets both at the same t.
// Brute force keeps the first it tests, the first in the scene's order; so
// does the BVH, whatever order it tests them in, so that every structure
// gives the same hit.
class NearestHit {
 public:
  explicit NearestHit(Hit& hit) : hit_(hit) {}

  // Offers the hit of one primitive, found by `intersect(candidate)`.
  template <typename Intersect>
  bool offer(PrimitiveRef ref, Intersect&& intersect) {
    Hit candidate = hit_;
    candidate.t = std::nextafter(hit_.t, kInfinity);  // an equal t too
    if (!intersect(candidate)) return false;
    if (candidate.t == hit_.t && !(found_ && comesBefore(ref, ref_))) return false;
    hit_ = candidate;
    ref_ = ref;
    found_ = true;
    return true;
  }

 private:
  static bool comesBefore(PrimitiveRef a, PrimitiveRef b) {
    return a.shape < b.shape || (a.shape == b.shape && a.primitive < b.primitive);
  }

  Hit& hit_;
  PrimitiveRef ref_{0, 0};
  bool found_ = false;
};

bool Bvh::nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  NearestHit nearest(hit);
  bool found = false;
  for (int shape : unbounded_) {
    found |= nearest.offer({static_cast<std::uint32_t>(shape), 0}, [&](Hit& candidate) {
      return shapes_[shape]->intersect(ray, tMin, candidate, counters);
    });
  }
  traverse(ray, tMin, hit.t, counters, [&](const BvhNode& leaf) {
    for (std::uint32_t i = leaf.offset; i < leaf.offset + leaf.primitiveCount; ++i) {
      found |= nearest.offer(primitives_[i].ref, [&](Hit& candidate) {
        return intersectPrimitive(primitives_[i], ray, tMin, candidate, counters);
      });
    }
    return true;
  });
  return found;
}

void Bvh::visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                         IntersectionCounters& counters) const {
  for (int shape : unbounded_)
    if (crosses(*shapes_[shape], ray, tMin, tMax, counters) && !visitor.crossed(shape)) return;
  traverse(ray, tMin, tMax, counters, [&](const BvhNode& leaf) {
    for (std::uint32_t i = leaf.offset; i < leaf.offset + leaf.primitiveCount; ++i) {
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
