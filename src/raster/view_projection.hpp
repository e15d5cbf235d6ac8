// The viewing transform and the perspective projection of the visible-surface
// algorithms: the original RISE report's Matriz3D and Calcular_i_j.
//
// Matriz3D moves the world so that the observer is at the origin and its
// U, V, N axes (right, up, and the direction it looks in, the normal of the
// screen) are the coordinate axes: a translation T by -Obs, then the rotation
// R whose rows are U, V and N. In these camera coordinates (u, v, n) a point
// lies n in front of the eye, and the perspective projection divides by n:
// (u / n, v / n) on the screen plane at distance 1. Calcular_i_j maps that
// plane onto pixels, with (0, 0) the top-left corner of the image and pixel
// (i, j)'s centre at (i + 1/2, j + 1/2).
//
// The axes and the extent of the screen are those of the ray tracer's
// ViewFrame, so that the point this projection puts at a raster position is
// the point the ray tracer's primary ray through that position meets.
//
// A camera with an aperture is a thin lens: seen from a point of the lens
// instead of the eye, the projection is the same but for a shift that keeps
// the plane in focus where it was (Haeberli and Akeley 1990). A point
// (u, v, n) of the eye's camera coordinates, seen from the lens point
// (lu, lv, 0) through the point where that line crosses the focal plane
// n = F, lands where the eye sees that crossing:
//
//   x = xScale ((u - lu) / n + lu / F) + xOffset
//
// the projection from the lens point, shifted by xScale lu / F (and likewise
// for y). Points on the focal plane stay put; the others move with the lens
// point, the more the farther they are from that plane, and averaging images
// over the lens blurs them as the ray tracer's thin-lens rays do.
#pragma once

#include <array>

#include "core/math.hpp"
#include "scene/camera.hpp"

namespace rise {

class ViewProjection {
 public:
  // Each pixel (i, j) is to show the scene at the raster position
  // (i + sampleOffset.x, j + sampleOffset.y); the default is its centre. The
  // projection shifts the image by the offset's distance from the centre, so
  // that the algorithms always sample at pixel centres: rendering several
  // times with offsets spread over the pixel and averaging the images
  // anti-aliases them (an accumulation buffer).
  // `lensSample` in the unit square picks the point of the lens the image is
  // seen from (ViewFrame::lensPoint); the eye for a pinhole camera.
  explicit ViewProjection(const ViewFrame& frame, Vec2 sampleOffset = Vec2(0.5f),
                          Vec2 lensSample = Vec2(0.5f));

  // Matriz3D: R T, from world to camera coordinates (u, v, n).
  const Mat4& cameraFromWorld() const { return cameraFromWorld_; }
  Vec3 toCamera(const Vec3& world) const { return Vec3(cameraFromWorld_ * glm::vec4(world, 1.0f)); }

  // The raster position of a point in front of the eye (n > 0): where the
  // projection from the point of the lens puts it, moved by the shift.
  Vec2 toRaster(const Vec3& camera) const {
    const float inverseDepth = 1.0f / camera.z;
    return Vec2(xScale_ * camera.x * inverseDepth + xCentre_,
                yScale_ * camera.y * inverseDepth + yCentre_) +
           shift_;
  }

  // The direction, in camera coordinates, from the eye through a raster
  // position: (u / n, v / n, 1), the inverse of toRaster. Both are affine in
  // the raster coordinates.
  Vec3 cameraDirection(const Vec2& raster) const {
    const Vec2 unshifted = raster - shift_;
    return {(unshifted.x - xCentre_) / xScale_, (unshifted.y - yCentre_) / yScale_, 1.0f};
  }

  // The affine function of raster position a x + b y + c that equals the
  // linear function dot(directionForm, cameraDirection((x, y))).
  glm::dvec3 rasterForm(const glm::dvec3& directionForm) const;

  // How far the image is moved in raster coordinates: the pixel's centre
  // less the sample offset.
  Vec2 shift() const { return shift_; }
  // The same projection, not moved: what every pass that sees the scene
  // from the same point of the lens has in common.
  ViewProjection unshifted() const;

  // The view volume in camera coordinates, as five planes (a, b, c, d) with
  // a u + b v + c n + d >= 0 inside: in front of the near plane at distance
  // `nearDistance`, and within `margin` pixels of the four sides of the image
  // not moved; the same volume, then, whatever the sample offset.
  std::array<glm::vec4, 5> viewVolume(float nearDistance, float margin) const;

  const Vec3& eye() const { return eye_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Mat4 cameraFromWorld_;
  Vec3 eye_;
  int width_, height_;
  // raster x = (xScale u / n + xCentre) + shift.x, and likewise y.
  float xScale_, xCentre_, yScale_, yCentre_;
  Vec2 shift_;
};

}  // namespace rise
