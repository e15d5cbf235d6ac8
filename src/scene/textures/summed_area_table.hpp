// A summed-area table (F. C. Crow, "Summed-Area Tables for Texture Mapping",
// SIGGRAPH 1984): at each corner of the texel grid, the sum of the texels
// above and to the left of it, so that the mean over any axis-aligned
// rectangle of the texture takes four look-ups, however large the
// rectangle: a box filter over the footprint's bounding rectangle, which
// follows a footprint long along u or v (a floor seen straight down its
// length, the rows of a cylinder's cap) but not a slanting one.
#pragma once

#include <vector>

#include "core/image.hpp"

namespace rise {

class SummedAreaTable {
 public:
  // Sums the texels once, row by row.
  explicit SummedAreaTable(const Image& image);

  // The mean of the image, repeated in both directions, over the rectangle
  // between `low` and `high`, in image coordinates (texels, x right, y down).
  Color meanOver(const Vec2& low, const Vec2& high) const;

 private:
  // The sum over [0, x) x [0, y) of the repeated image, the texels constant
  // over their squares: bilinear between the table's corners, which is
  // exact.
  glm::dvec3 sumTo(double x, double y) const;
  // The table at a corner of one copy of the image: 0 <= x <= width,
  // 0 <= y <= height.
  const glm::dvec3& corner(long long x, long long y) const;

  int width_;
  int height_;
  // In double precision: the sums of a large image outgrow a float's
  // 24 bits long before they are divided back into a mean.
  std::vector<glm::dvec3> sums_;
};

}  // namespace rise
