#include "reports/step_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "io/image_io.hpp"

namespace rise {
namespace {

constexpr const char* kOtherRole = "other";

Color linearColourOf(const std::string& hex) {
  const auto channel = [&](std::size_t at) {
    return linearFromSrgb(static_cast<float>(std::stoi(hex.substr(at, 2), nullptr, 16)) / 255.0f);
  };
  return {channel(1), channel(3), channel(5)};
}

Color colourOfRole(const std::string& role) {
  const auto& colours = shapeColours();
  const auto found = std::find_if(colours.begin(), colours.end(),
                                  [&](const auto& entry) { return entry.first == role; });
  if (found != colours.end()) return linearColourOf(found->second);
  return colourOfRole(kOtherRole);
}

void plot(Image& image, int x, int y, const Color& colour) {
  if (x >= 0 && y >= 0 && x < image.width() && y < image.height()) image.at(x, y) = colour;
}

// Steps one pixel at a time along the longer axis, so the line has no gaps.
void drawLine(Image& image, Vec2 from, Vec2 to, const Color& colour) {
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

const std::vector<std::pair<std::string, std::string>>& shapeColours() {
  static const std::vector<std::pair<std::string, std::string>> colours = {
      {"window", "#ffcc00"}, {"polygon", "#00e5ff"}, {kOtherRole, "#ff4081"}, {"behind", "#7c4dff"},
      {"front", "#00e676"},  {"span", "#ffea00"},    {"edge", "#ff9100"},     {"tile", "#ffffff"}};
  return colours;
}

void drawShapes(Image& image, const std::vector<StepShape>& shapes) {
  for (const StepShape& shape : shapes) {
    const Color colour = colourOfRole(shape.role);
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
