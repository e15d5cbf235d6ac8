#include "raster/axis_view.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "raster/polygon_clipping.hpp"

namespace rise {

Vec3 AxisView::toView(const Vec3& world) const {
  const Vec3 offset = world - origin;
  return {glm::dot(offset, right), glm::dot(offset, up), glm::dot(offset, forward)};
}

Vec2 AxisView::toMap(const Vec3& view) const {
  const float extent = perspective ? view.z : halfWidth;
  const float half = 0.5f * static_cast<float>(size);
  return {(view.x / extent + 1.0f) * half, (1.0f - view.y / extent) * half};
}

float AxisView::texelSize(float depth) const {
  return 2.0f * (perspective ? depth : halfWidth) / static_cast<float>(size);
}

std::vector<AxisView> cubeViews(const Vec3& centre, int size) {
  const std::array<std::pair<Vec3, Vec3>, 6> axes = {{{{1, 0, 0}, {0, 1, 0}},
                                                      {{-1, 0, 0}, {0, 1, 0}},
                                                      {{0, 1, 0}, {0, 0, 1}},
                                                      {{0, -1, 0}, {0, 0, 1}},
                                                      {{0, 0, 1}, {0, 1, 0}},
                                                      {{0, 0, -1}, {0, 1, 0}}}};
  std::vector<AxisView> views;
  for (const auto& [forward, up] : axes)
    views.push_back({centre, glm::cross(forward, up), up, forward, true, 0.0f, size});
  return views;
}

int cubeFaceOf(const Vec3& offset) {
  const Vec3 size = glm::abs(offset);
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  return 2 * axis + (offset[axis] < 0.0f ? 1 : 0);
}

namespace {

// The planes a.x + b.y + c.z + d >= 0, in view coordinates, of what a view
// sees, a texel of margin beyond its sides: four for an orthographic view,
// five with the near plane for a perspective one.
std::span<const glm::vec4> viewVolume(const AxisView& view, std::array<glm::vec4, 5>& planes) {
  const float widened = 1.0f + 2.0f / static_cast<float>(view.size);
  if (view.perspective) {
    planes = {{{-1.0f, 0.0f, widened, 0.0f},
               {1.0f, 0.0f, widened, 0.0f},
               {0.0f, -1.0f, widened, 0.0f},
               {0.0f, 1.0f, widened, 0.0f},
               {0.0f, 0.0f, 1.0f, -kAxisViewNear}}};
    return planes;
  }
  const float side = widened * view.halfWidth;
  planes = {{{-1.0f, 0.0f, 0.0f, side},
             {1.0f, 0.0f, 0.0f, side},
             {0.0f, -1.0f, 0.0f, side},
             {0.0f, 1.0f, 0.0f, side},
             {}}};
  return std::span<const glm::vec4>(planes).first(4);
}

}  // namespace

bool PolygonInView::project(const AxisView& view, std::span<const Vec3> corners) {
  view_ = &view;
  polygon_.clear();
  for (const Vec3& corner : corners) polygon_.push_back(view.toView(corner));
  std::array<glm::vec4, 5> planes;
  for (const glm::vec4& plane : viewVolume(view, planes)) {
    if (polygon_.empty()) break;
    splitPolygon(polygon_, plane, 0.0f, inside_, outside_);
    polygon_.swap(inside_);
  }
  if (polygon_.size() < 3) return false;
  // On the map each corner is (x, y, affine depth), and the polygon is flat.
  for (Vec3& corner : polygon_) corner = Vec3(view.toMap(corner), view.affineDepth(corner.z));
  // The plane of the corners, from the widest triangle of the fan: a clipped
  // corner may lie on its neighbours' line.
  corner_ = glm::dvec3(polygon_[0]);
  normal_ = glm::dvec3(0.0);
  for (std::size_t i = 2; i < polygon_.size(); ++i) {
    const glm::dvec3 fan =
        glm::cross(glm::dvec3(polygon_[i - 1]) - corner_, glm::dvec3(polygon_[i]) - corner_);
    if (std::abs(fan.z) > std::abs(normal_.z)) normal_ = fan;
  }
  if (normal_.z == 0.0) return false;  // seen edge-on
  coverage_.reset(polygon_);
  return true;
}

float PolygonInView::depthAt(int x, int y) const {
  const double affine =
      corner_.z -
      (normal_.x * (x + 0.5 - corner_.x) + normal_.y * (y + 0.5 - corner_.y)) / normal_.z;
  return view_->depthOfAffine(static_cast<float>(affine));
}

}  // namespace rise
