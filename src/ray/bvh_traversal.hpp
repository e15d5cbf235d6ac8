// What the two traversals of the BVH share: a ray's (bvh.cpp) and a packet's
// (bvh_packet_traversal.cpp). Private to those two files.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "ray/bvh.hpp"

namespace rise {
namespace bvh_traversal {

template <typename Floats>
Floats maximum(Floats a, Floats b) {
  return a > b ? a : b;
}
template <typename Floats>
Floats minimum(Floats a, Floats b) {
  return a < b ? a : b;
}

// A box's exit is pushed out by a few ulps (T. Ize, "Robust BVH Ray
// Traversal", JCGT 2(2), 2013), so that rounding never loses a box a ray
// grazes.
constexpr float kRobustExit = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();

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

// The next float above t: std::nextafter(t, infinity), without a call into
// the math library for the positive distances that hits have, nor for the
// infinity of a ray that has hit nothing yet.
inline float nextAbove(float t) {
  if (t > 0.0f && t < kInfinity) return std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) + 1);
  if (t == kInfinity) return t;
  return std::nextafter(t, kInfinity);
}

}  // namespace bvh_traversal

// A ray through the edge that two triangles share meets both at the same t.
// Brute force keeps the first it tests, the first in the scene's order; so
// does the BVH, whatever order it tests them in, so that every structure
// gives the same hit.
class NearestHit {
 public:
  NearestHit() = default;  // to be given its hit
  explicit NearestHit(Hit& hit) : hit_(&hit) {}

  // Offers the hit of one primitive, found by `intersect(hit)`, which
  // overwrites the hit it finds nearer. The hit is tested in place and put
  // back field by field when it loses a tie: a copy of the whole, read just
  // after the test wrote it field by field, would wait for those writes.
  template <typename Intersect>
  bool offer(PrimitiveRef ref, Intersect&& intersect) {
    const float t = hit_->t;
    const Shape* const shape = hit_->shape;
    const int primitive = hit_->primitive;
    const Vec2 barycentric = hit_->barycentric;
    hit_->t = bvh_traversal::nextAbove(t);  // an equal t too
    if (intersect(*hit_) && (hit_->t != t || (found_ && comesBefore(ref, ref_)))) {
      ref_ = ref;
      found_ = true;
      return true;
    }
    hit_->t = t;
    hit_->shape = shape;
    hit_->primitive = primitive;
    hit_->barycentric = barycentric;
    return false;
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

inline bool Bvh::crossUnbounded(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                                IntersectionCounters& counters) const {
  for (int shape : unbounded_)
    if (crosses(*shapes_[shape], ray, tMin, tMax, counters) && !visitor.crossed(shape))
      return false;
  return true;
}

inline bool Bvh::crossLeaf(std::uint32_t first, std::uint32_t count, const Ray& ray, float tMin,
                           float tMax, CrossingVisitor& visitor,
                           IntersectionCounters& counters) const {
  for (std::uint32_t i = first; i < first + count; ++i) {
    Hit crossing;
    crossing.t = tMax;
    if (intersectPrimitive(primitives_[i], ray, tMin, crossing, counters) &&
        !visitor.crossed(static_cast<int>(primitives_[i].ref.shape)))
      return false;
  }
  return true;
}

}  // namespace rise
