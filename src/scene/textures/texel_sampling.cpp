#include "scene/textures/texel_sampling.hpp"

#include <cmath>

namespace rise {

namespace {

long long wrapped(long long index, int size) {
  const long long remainder = index % size;
  return remainder < 0 ? remainder + size : remainder;
}

}  // namespace

const Color& repeatedTexel(const Image& image, long long x, long long y) {
  return image.at(static_cast<int>(wrapped(x, image.width())),
                  static_cast<int>(wrapped(y, image.height())));
}

Color nearestAt(const Image& image, const Vec2& uv) {
  const Vec2 texel = texelCoordinates(image, uv);
  return repeatedTexel(image, static_cast<long long>(std::floor(texel.x)),
                       static_cast<long long>(std::floor(texel.y)));
}

Color bilinearAt(const Image& image, const Vec2& uv) {
  const Vec2 texel = texelCoordinates(image, uv) - Vec2(0.5f);
  const float left = std::floor(texel.x), top = std::floor(texel.y);
  const float across = texel.x - left, down = texel.y - top;
  const auto column = static_cast<long long>(left);
  const auto row = static_cast<long long>(top);
  const Color upper =
      glm::mix(repeatedTexel(image, column, row), repeatedTexel(image, column + 1, row), across);
  const Color lower = glm::mix(repeatedTexel(image, column, row + 1),
                               repeatedTexel(image, column + 1, row + 1), across);
  return glm::mix(upper, lower, down);
}

}  // namespace rise
