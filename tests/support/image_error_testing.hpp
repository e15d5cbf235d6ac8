// How far an image is from another in linear colour, for estimates held to a
// reference: the root mean square of the channels' differences.
#pragma once

#include <cmath>
#include <cstddef>

#include "core/image.hpp"

namespace rise {

inline double rmse(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Color d = a.pixels()[i] - b.pixels()[i];
    sum += glm::dot(d, d) / 3.0;
  }
  return std::sqrt(sum / static_cast<double>(a.pixels().size()));
}

}  // namespace rise
