// How far an image is from another in linear colour, for an estimate held to
// a reference (a render of many samples, another renderer's): the root mean
// square of the channels' differences, and the same over the reference's own
// root mean square, so that an error reads the same in a dim scene as in a
// bright one.
#pragma once

#include <cmath>
#include <cstddef>

#include "core/image.hpp"

namespace rise {

// Of two images of the same size.
inline double rmse(const Image& image, const Image& reference) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixels().size(); ++i) {
    const Color difference = image.pixels()[i] - reference.pixels()[i];
    sum += glm::dot(difference, difference) / 3.0;
  }
  return std::sqrt(sum / static_cast<double>(image.pixels().size()));
}

// 0 for a black reference matched exactly; infinite for any other image
// beside a black reference.
inline double relativeRmse(const Image& image, const Image& reference) {
  const Image black(reference.width(), reference.height());
  const double error = rmse(image, reference);
  const double scale = rmse(reference, black);
  if (scale > 0.0) return error / scale;
  return error > 0.0 ? INFINITY : 0.0;
}

}  // namespace rise
