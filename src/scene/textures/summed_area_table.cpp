#include "scene/textures/summed_area_table.hpp"

#include <cmath>

namespace rise {

SummedAreaTable::SummedAreaTable(const Image& image)
    : width_(image.width()),
      height_(image.height()),
      sums_(static_cast<std::size_t>(width_ + 1) * (height_ + 1), glm::dvec3(0.0)) {
  for (int y = 0; y < height_; ++y) {
    glm::dvec3 row(0.0);
    for (int x = 0; x < width_; ++x) {
      row += glm::dvec3(image.at(x, y));
      sums_[static_cast<std::size_t>(y + 1) * (width_ + 1) + x + 1] = corner(x + 1, y) + row;
    }
  }
}

const glm::dvec3& SummedAreaTable::corner(long long x, long long y) const {
  return sums_[static_cast<std::size_t>(y) * (width_ + 1) + static_cast<std::size_t>(x)];
}

glm::dvec3 SummedAreaTable::sumTo(double x, double y) const {
  // Whole copies of the image, then what is left of the last in each
  // direction: the sum over [0, qx w + rx) x [0, qy h + ry).
  const double columns = std::floor(x / width_), rows = std::floor(y / height_);
  const double restX = x - columns * width_, restY = y - rows * height_;
  const auto within = [&](double cx, double cy) {
    const double left = std::min(std::floor(cx), static_cast<double>(width_ - 1));
    const double top = std::min(std::floor(cy), static_cast<double>(height_ - 1));
    const double fx = cx - left, fy = cy - top;
    const auto i = static_cast<long long>(left), j = static_cast<long long>(top);
    return (1.0 - fy) * ((1.0 - fx) * corner(i, j) + fx * corner(i + 1, j)) +
           fy * ((1.0 - fx) * corner(i, j + 1) + fx * corner(i + 1, j + 1));
  };
  return columns * rows * corner(width_, height_) + columns * within(width_, restY) +
         rows * within(restX, height_) + within(restX, restY);
}

Color SummedAreaTable::meanOver(const Vec2& low, const Vec2& high) const {
  const glm::dvec3 sum =
      sumTo(high.x, high.y) - sumTo(low.x, high.y) - sumTo(high.x, low.y) + sumTo(low.x, low.y);
  const double area = (static_cast<double>(high.x) - low.x) * (static_cast<double>(high.y) - low.y);
  return Color(sum / area);
}

}  // namespace rise
