#include "raster/view_projection.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rise {

ViewProjection::ViewProjection(const ViewFrame& frame, Vec2 sampleOffset, Vec2 lensSample)
    : width_(frame.width()), height_(frame.height()) {
  const Vec2 onLens = frame.lensPoint(lensSample);
  eye_ = frame.eye() + onLens.x * frame.right() + onLens.y * frame.up();
  const Mat4 translation = glm::translate(Mat4(1.0f), -eye_);
  // glm matrices are indexed by column: rotation[c][r]. Its rows are U, V, N.
  Mat4 rotation(1.0f);
  for (int c = 0; c < 3; ++c) {
    rotation[c][0] = frame.right()[c];
    rotation[c][1] = frame.up()[c];
    rotation[c][2] = frame.forward()[c];
  }
  cameraFromWorld_ = rotation * translation;

  // ViewFrame::primaryRay's mapping, inverted: u / n = (2 x / width - 1)
  // halfWidth and v / n = (1 - 2 y / height) halfHeight at the raster (x, y),
  // then shifted so that the sample lands on the pixel's centre.
  xScale_ = 0.5f * static_cast<float>(width_) / frame.halfWidth();
  yScale_ = -0.5f * static_cast<float>(height_) / frame.halfHeight();
  const Vec2 focusShift = onLens / frame.focalDistance();
  xCentre_ = 0.5f * static_cast<float>(width_) + xScale_ * focusShift.x;
  yCentre_ = 0.5f * static_cast<float>(height_) + yScale_ * focusShift.y;
  shift_ = Vec2(0.5f) - sampleOffset;
}

ViewProjection ViewProjection::unshifted() const {
  ViewProjection view = *this;
  view.shift_ = Vec2(0.0f);
  return view;
}

glm::dvec3 ViewProjection::rasterForm(const glm::dvec3& directionForm) const {
  // dot(form, ((x - xOffset) / xScale, (y - yOffset) / yScale, 1)), with
  // xOffset = xCentre + shift.x and yOffset likewise.
  const double a = directionForm.x / xScale_;
  const double b = directionForm.y / yScale_;
  const double xOffset = static_cast<double>(xCentre_) + shift_.x;
  const double yOffset = static_cast<double>(yCentre_) + shift_.y;
  return {a, b, directionForm.z - a * xOffset - b * yOffset};
}

std::array<glm::vec4, 5> ViewProjection::viewVolume(float nearDistance, float margin) const {
  // Raster x >= -margin is n (x + margin) >= 0, that is
  // xScale u + (xCentre + margin) n >= 0; likewise for the other sides.
  const float right = static_cast<float>(width_) + margin;
  const float bottom = static_cast<float>(height_) + margin;
  return {{
      {0.0f, 0.0f, 1.0f, -nearDistance},
      {xScale_, 0.0f, xCentre_ + margin, 0.0f},
      {-xScale_, 0.0f, right - xCentre_, 0.0f},
      {0.0f, yScale_, yCentre_ + margin, 0.0f},
      {0.0f, -yScale_, bottom - yCentre_, 0.0f},
  }};
}

}  // namespace rise
