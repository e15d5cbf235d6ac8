#pragma once

#include "core/math.hpp"

namespace rise {

// An object's placement in a scene file: scale first, then rotate about the
// x, y and z axes in that order (degrees), then translate.
struct TransformSpec {
  Vec3 scale{1.0f};
  Vec3 rotateDegrees{0.0f};
  Vec3 translate{0.0f};

  bool isIdentity() const {
    return scale == Vec3(1.0f) && rotateDegrees == Vec3(0.0f) && translate == Vec3(0.0f);
  }
};

Mat4 worldFromObject(const TransformSpec& spec);

}  // namespace rise
