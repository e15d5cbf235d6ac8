#pragma once

#include <optional>

#include "core/math.hpp"
#include "core/ray.hpp"
#include "core/warps.hpp"

namespace rise {

// The viewer, as in the scene file: where it stands, where it looks, which way
// is up, and the vertical field of view; then what a real camera adds (Cook,
// Porter & Carpenter 1984): a lens of some diameter focused at some distance,
// and a shutter open for an interval of time.
struct Camera {
  Vec3 position{0.0f, 0.0f, -5.0f};
  Vec3 lookAt{0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  // Where an animation's camera stands at its end (the scene file's camera
  // `motion`), or nothing when it stays.
  struct Placement {
    Vec3 position, lookAt, up;
  };
  std::optional<Placement> endPlacement;
  float fovDegrees = 50.0f;
  float aperture = 0.0f;       // the lens's diameter; 0 is a pinhole, everything sharp
  float focalDistance = 0.0f;  // from the eye to the plane in focus; 0: the look_at point's
  float shutterOpen = 0.0f;
  float shutterClose = 0.0f;  // equal to shutterOpen: an instant, no motion blur

  // The span of the scene's time the shutter covers: shapes stand at their
  // `transform` at time 0 and at their `motion` at time 1, an MD2 model in
  // the first keyframe of its `frames` at 0 and in the last at 1. A still
  // image's shutter covers all of it; an animation's frame covers a part
  // (cameraForFrame).
  float sceneTimeOpen = 0.0f;
  float sceneTimeClose = 1.0f;

  bool hasMotionBlur() const { return shutterClose > shutterOpen; }
  // The scene's time at `fraction` of the shutter interval: a camera without
  // one sees the instant it opens.
  float sceneTime(float fraction) const {
    return hasMotionBlur() ? sceneTimeOpen + fraction * (sceneTimeClose - sceneTimeOpen)
                           : sceneTimeOpen;
  }
};

// The camera of frame `frame` (from 0) of an animation of `frames` frames:
// the frames cut the scene's time from 0 to 1 into equal parts, frame f's
// beginning at f / frames, so that a cycle loops; its shutter, read in
// frames (a shutter [0, 0.5] is open for the first half of each), covers
// that much of its part. The camera stands where it is at the frame's
// beginning, between its placement and its end placement.
Camera cameraForFrame(const Camera& camera, int frame, int frames);

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
  // At the instant the shutter opens. Inline, so that a packet of rays has
  // each made in its place rather than copied there.
  Ray primaryRay(float x, float y) const {
    const float sx = (2.0f * x / static_cast<float>(width_) - 1.0f) * halfWidth_;
    const float sy = (1.0f - 2.0f * y / static_cast<float>(height_)) * halfHeight_;
    return Ray{eye_, glm::normalize(forward_ + sx * right_ + sy * up_), time_};
  }

  // The point of the lens chosen by the sample `lens` in the unit square, as
  // offsets along right and up from the eye: uniform over the lens's disk,
  // (0, 0) with no aperture.
  Vec2 lensPoint(const Vec2& lens) const { return lensRadius_ * squareToDisk(lens); }
  float lensRadius() const { return lensRadius_; }
  // The distance from the eye to the plane in focus, along forward.
  float focalDistance() const { return focalDistance_; }

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
  float time_;
  float lensRadius_;
  float focalDistance_;
};

// The ray through the raster position from the point of a thin lens that
// `lens` picks (ViewFrame::lensPoint), aimed at the point the pinhole ray
// meets on the plane in focus; the pinhole ray itself with no aperture.
// Inline, as ViewFrame::primaryRay is, and one named ray throughout, so that
// the ray is made where its caller keeps it: a copy of a ray just written
// field by field would wait for the writes.
inline Ray thinLensRay(const ViewFrame& view, const Vec2& raster, const Vec2& lens) {
  Ray ray = view.primaryRay(raster.x, raster.y);
  if (view.lensRadius() == 0.0f) return ray;
  const Vec3 inFocus = ray.at(view.focalDistance() / glm::dot(ray.direction, view.forward()));
  const Vec2 onLens = view.lensPoint(lens);
  ray.origin = view.eye() + onLens.x * view.right() + onLens.y * view.up();
  ray.direction = glm::normalize(inFocus - ray.origin);
  return ray;
}

}  // namespace rise
