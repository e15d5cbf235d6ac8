#pragma once

#include "core/math.hpp"
#include "core/ray.hpp"

namespace rise {

// The viewer, as in the scene file: where it stands, where it looks, which way
// is up, and the vertical field of view.
struct Camera {
  Vec3 position{0.0f, 0.0f, -5.0f};
  Vec3 lookAt{0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float fovDegrees = 50.0f;
};

// The camera's orthonormal frame for an image of a given size (the textbook's
// U, V, N axes): right, up and forward, and the extent of the image plane at
// distance 1. Every algorithm, ray tracer or rasteriser, views the scene
// through this one frame.
class ViewFrame {
 public:
  ViewFrame(const Camera& camera, int width, int height);

  // The ray from the eye through the continuous raster position (x, y):
  // (0, 0) is the top-left corner of the image, (width, height) the
  // bottom-right, so pixel (i, j)'s centre is (i + 0.5, j + 0.5).
  Ray primaryRay(float x, float y) const;

  const Vec3& eye() const { return eye_; }
  const Vec3& right() const { return right_; }
  const Vec3& up() const { return up_; }
  const Vec3& forward() const { return forward_; }
  float halfHeight() const { return halfHeight_; }
  float halfWidth() const { return halfWidth_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Vec3 eye_, right_, up_, forward_;
  float halfWidth_, halfHeight_;
  int width_, height_;
};

}  // namespace rise
