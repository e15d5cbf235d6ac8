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
  const Vec2 shift = Vec2(0.5f) - sampleOffset;
  xScale_ = 0.5f * static_cast<float>(width_) / frame.halfWidth();
  yScale_ = -0.5f * static_cast<float>(height_) / frame.halfHeight();
  const Vec2 focusShift = onLens / frame.focalDistance();
  xOffset_ = 0.5f * static_cast<float>(width_) + shift.x + xScale_ * focusShift.x;
  yOffset_ = 0.5f * static_cast<float>(height_) + shift.y + yScale_ * focusShift.y;
}

glm::dvec3 ViewProjection::rasterForm(const glm::dvec3& directionForm) const {
  // dot(form, ((x - xOffset) / xScale, (y - yOffset) / yScale, 1)).
  const double a = directionForm.x / xScale_;
  const double b = directionForm.y / yScale_;
  return {a, b, directionForm.z - a * xOffset_ - b * yOffset_};
}

std::array<glm::vec4, 5> ViewProjection::viewVolume(float nearDistance, float margin) const {
  // Raster x >= -margin is n (x + margin) >= 0, that is
  // xScale u + (xOffset + margin) n >= 0; likewise for the other sides.
  const float right = static_cast<float>(width_) + margin;
  const float bottom = static_cast<float>(height_) + margin;
  return {{
      {0.0f, 0.0f, 1.0f, -nearDistance},
      {xScale_, 0.0f, xOffset_ + margin, 0.0f},
      {-xScale_, 0.0f, right - xOffset_, 0.0f},
      {0.0f, yScale_, yOffset_ + margin, 0.0f},
      {0.0f, -yScale_, bottom - yOffset_, 0.0f},
  }};
}

}  // namespace rise
