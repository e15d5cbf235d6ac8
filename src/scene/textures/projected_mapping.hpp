// Projected texture mappings, chosen per object instead of the shape's own
// coordinates: the texture is laid over a simple surface around the object
// and carried onto it by projection, the two-part mapping of E. A. Bier and
// K. R. Sloan ("Two-Part Texture Mappings", IEEE CG&A 6(9), 1986). Each
// works in the object's own space, around its bounding box, so that the
// texture moves with the object:
//
//   spherical    longitude and latitude of the direction from the box's
//                centre around an axis (y), as on a globe
//   cylindrical  the turn around the axis through the centre, and the height
//                along it from the bottom of the box (v = 0) to its top (1)
//   planar       along z onto the box's x-y extent: the unit square as seen
//                from -z, in front, where cameras usually stand
//   box          a cube mapping: each point onto the face of the box that
//                its surface faces most, each face the unit square
//
// The spherical and cylindrical coordinates wrap at a seam, where u jumps
// from 1 back to 0, and u is undefined on their axis (at the poles).
#pragma once

#include <array>

#include "core/bounds.hpp"
#include "core/math.hpp"
#include "scene/shape.hpp"

namespace rise {

enum class Projection { Spherical, Cylindrical, Planar, Box };

// A projection and, for the spherical and cylindrical ones, the unit axis
// they turn around.
struct Mapping {
  Projection projection = Projection::Spherical;
  Vec3 axis{0.0f, 1.0f, 0.0f};
};

class ProjectedMapping {
 public:
  // Around `bounds`, the object's box in its own space.
  ProjectedMapping(const Mapping& mapping, const Bounds3& bounds);

  // The coordinates at a point of the surface whose outward normal there is
  // `normal` (which a box mapping projects from the face it faces).
  Vec2 uvAt(const Vec3& position, const Vec3& normal) const;
  // dP/du and dP/dv along the surface at that point.
  void tangentsAt(const Vec3& position, const Vec3& normal, Vec3& dpdu, Vec3& dpdv) const;
  // Both, at the point of `surface` with its normal.
  void mapOnto(SurfacePoint& surface) const;
  // How far the coordinates move from `from` to `to` at a nearby point: the
  // short way around where u wraps.
  Vec2 step(const Vec2& from, const Vec2& to) const;

  // The coordinates of the corners of a flat triangle (counter-clockwise
  // around its outward normal), which a renderer interpolates across it: all
  // from the face its normal faces, for a box mapping. For the turning ones,
  // the corners' u go the short way around the axis, across the seam if it
  // does (u beyond 1: textures repeat); a corner on the axis takes the mean
  // u of the others, and a triangle around the axis one u for all.
  std::array<Vec2, 3> cornerUvs(const std::array<Vec3, 3>& corners) const;

  // Whether u turns around an axis (spherical, cylindrical): then the
  // coordinates are not affine across a triangle, and interpolating its
  // corners' is exact only on small triangles.
  bool turns() const;
  const Bounds3& bounds() const { return bounds_; }

 private:
  bool isOnAxis(const Vec3& position) const;
  // The face of the box a flat projection projects from: the front, for
  // planar; for box, the one the surface faces most.
  Vec3 faceProjectedFrom(const Vec3& normal) const;

  Mapping mapping_;
  Bounds3 bounds_;
  // Half the box's extent along the axis (cylindrical v).
  float halfHeight_;
};

}  // namespace rise
