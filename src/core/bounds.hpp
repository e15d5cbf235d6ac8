#pragma once

#include "core/math.hpp"

namespace rise {

// An axis-aligned box, the bounding volume of acceleration structures. The
// default box is empty (min above max), so that growing it by points or
// boxes gives their bounds.
struct Bounds3 {
  Vec3 min{kInfinity};
  Vec3 max{-kInfinity};

  static Bounds3 infinite() { return {Vec3(-kInfinity), Vec3(kInfinity)}; }

  bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  bool isFinite() const {
    return glm::all(glm::lessThan(glm::abs(min), Vec3(kInfinity))) &&
           glm::all(glm::lessThan(glm::abs(max), Vec3(kInfinity)));
  }

  void grow(const Vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
  }
  void grow(const Bounds3& other) {
    min = glm::min(min, other.min);
    max = glm::max(max, other.max);
  }

  // Corner 0 is min, corner 7 is max; bit k of the index picks max along axis k.
  Vec3 corner(int index) const {
    return {(index & 1) ? max.x : min.x, (index & 2) ? max.y : min.y, (index & 4) ? max.z : min.z};
  }

  Vec3 extent() const { return max - min; }
  Vec3 centre() const { return 0.5f * (min + max); }
  float surfaceArea() const {
    const Vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

}  // namespace rise
