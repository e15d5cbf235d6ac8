// Colours are linear RGB triples; the output encoding (sRGB or linear) is
// chosen only when an image is written.
#pragma once

#include "core/math.hpp"

namespace rise {

using Color = glm::vec3;

inline float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace rise
