#include "reports/step_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/image_io.hpp"
#include "reports/colours.hpp"

namespace rise {
namespace {

Color linearColourOf(const std::string& hex) {
  const auto bytes = bytesOfColour(hex);
  return {linearFromSrgb(bytes[0] / 255.0f), linearFromSrgb(bytes[1] / 255.0f),
          linearFromSrgb(bytes[2] / 255.0f)};
}

void plot(Image& image, int x, int y, const Color& colour) {
  if (x >= 0 && y >= 0 && x < image.width() && y < image.height()) image.at(x, y) = colour;
}

// Cuts the segment to the image's rectangle, one pixel wider on each side
// (Liang and Barsky 1984), so that a corner far outside costs no steps; false
// if nothing of it is left. In doubles, so that a cut far from either end
// still lands within a pixel of the image's side.
bool clipToImage(const Image& image, Vec2& from, Vec2& to) {
  const glm::dvec2 start(from), delta = glm::dvec2(to) - start;
  const glm::dvec2 low(-1.0), high(image.width() + 1.0, image.height() + 1.0);
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    for (const auto& [towards, room] : {std::pair(-delta[axis], start[axis] - low[axis]),
                                        std::pair(delta[axis], high[axis] - start[axis])}) {
      if (!std::isfinite(towards) || !std::isfinite(room)) return false;
      if (towards == 0.0) {
        if (room < 0.0) return false;
        continue;
      }
      const double t = room / towards;
      if (towards < 0.0)
        enter = std::max(enter, t);
      else
        leave = std::min(leave, t);
    }
  }
  if (enter > leave) return false;
  from = Vec2(start + delta * enter);
  to = Vec2(start + delta * leave);
  return true;
}

// Steps one pixel at a time along the longer axis, so the line has no gaps.
void drawLine(Image& image, Vec2 from, Vec2 to, const Color& colour) {
  if (!clipToImage(image, from, to)) return;
  const int count =
      static_cast<int>(std::ceil(std::max(std::abs(to.x - from.x), std::abs(to.y - from.y))));
  for (int i = 0; i <= count; ++i) {
    const Vec2 point = count == 0 ? from : from + (to - from) * (static_cast<float>(i) / count);
    plot(image, static_cast<int>(std::floor(point.x)), static_cast<int>(std::floor(point.y)),
         colour);
  }
}

void drawOutline(Image& image, const std::vector<Vec2>& corners, bool closed, const Color& colour) {
  for (std::size_t i = 0; i + 1 < corners.size(); ++i)
    drawLine(image, corners[i], corners[i + 1], colour);
  if (closed && corners.size() > 2) drawLine(image, corners.back(), corners.front(), colour);
}

// A rectangle's corners are pixel edges; its outline is drawn on the pixels
// just inside them.
std::vector<Vec2> rectangleCorners(const std::vector<Vec2>& points) {
  const Vec2 low = glm::min(points[0], points[1]);
  const Vec2 high = glm::max(points[0], points[1]) - Vec2(1.0f);
  return {low, {high.x, low.y}, high, {low.x, high.y}};
}

}  // namespace

void drawShapes(Image& image, const std::vector<StepShape>& shapes) {
  for (const StepShape& shape : shapes) {
    const Color colour = linearColourOf(colourOfRole(shape.role));
    switch (shape.kind) {
      case StepShape::Kind::Rectangle:
        drawOutline(image, rectangleCorners(shape.points), true, colour);
        break;
      case StepShape::Kind::Polygon:
        drawOutline(image, shape.points, true, colour);
        break;
      case StepShape::Kind::Segment:
        drawOutline(image, shape.points, false, colour);
        break;
      case StepShape::Kind::Point:
        drawLine(image, shape.points[0] - Vec2(1.0f, 0.0f), shape.points[0] + Vec2(1.0f, 0.0f),
                 colour);
        drawLine(image, shape.points[0] - Vec2(0.0f, 1.0f), shape.points[0] + Vec2(0.0f, 1.0f),
                 colour);
        break;
    }
  }
}

}  // namespace rise
