#pragma once

#include "core/math.hpp"
#include "core/ray.hpp"
#include "scene/shape.hpp"

namespace rise {

// An object's placement in a scene file: scale first, then rotate about the
// x, y and z axes in that order (degrees), then translate.
struct TransformSpec {
  Vec3 scale{1.0f};
  Vec3 rotateDegrees{0.0f};
  Vec3 translate{0.0f};

  bool isIdentity() const {
    return scale == Vec3(1.0f) && rotateDegrees == Vec3(0.0f) && translate == Vec3(0.0f);
  }
};

Mat4 worldFromObject(const TransformSpec& spec);

// The spec a linear motion has reached at `time` in [0, 1]: scale, angles and
// translation each interpolated between `from` and `to`.
TransformSpec interpolate(const TransformSpec& from, const TransformSpec& to, float time);

// An affine map between a shape's own space and the world, with what it takes
// to carry rays in and surface points out: points and directions by the
// inverse, normals back by the inverse transpose.
class AffineMap {
 public:
  explicit AffineMap(const Mat4& worldFromObject);

  // The ray in object space. Its direction is not renormalised, so that t
  // means the same in both spaces.
  Ray toObject(const Ray& worldRay) const;
  SurfacePoint toWorld(const SurfacePoint& object) const;
  // A point of the surface and its normals in object space.
  SurfacePoint toObject(const SurfacePoint& world) const;
  Vec3 pointToWorld(const Vec3& point) const;
  // The box around the image of a box: an affine map takes a box to a
  // parallelepiped, which lies inside the box around its eight corners.
  Bounds3 boundsToWorld(const Bounds3& objectBox) const;

  const Mat4& worldFromObject() const { return worldFromObject_; }

 private:
  Mat4 worldFromObject_;
  Mat4 objectFromWorld_;
  Mat3 normalToWorld_;
};

}  // namespace rise
