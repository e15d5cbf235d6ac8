// The natural texture coordinates of the primitives: how each lays a unit
// square of texture (u to the right, v up, as an image is seen) over itself.
// Curved surfaces measure u around their axis and v along it; flat faces are
// mapped by projection onto their plane. The ray tracers (Shape::surfaceAt)
// and the tessellations (Shape::tessellate) take their coordinates from here,
// so that both draw a texture at the same place.
#pragma once

#include "core/math.hpp"

namespace rise {

// The fraction of a turn around the unit axis from the first direction of
// directionsAround(axis) (tessellation.hpp) to `direction`, in [0, 1),
// turning counter-clockwise seen from the axis's tip, as directionsAround
// does: on the outside of an upright surface u grows to the right.
float turnAroundAxis(const Vec3& axis, const Vec3& direction);

// The same, for the `step`th of `segments` directions of directionsAround:
// steps 0 to segments cover [0, 1] without a jump (a tessellation repeats
// its first column at the end, with u = 1).
float turnAtStep(float step, int segments);

// Longitude and latitude on the unit sphere around the axis: u as
// turnAroundAxis, v from 0 at the south pole (-axis) to 1 at the north.
Vec2 sphericalUv(const Vec3& axis, const Vec3& unitDirection);

// How a point of a surface around the unit axis moves as u (turnAroundAxis)
// grows, given the point's offset across the axis: a full turn, u from 0
// to 1, goes once around a circle of that radius.
Vec3 turnTangent(const Vec3& axis, const Vec3& acrossAxis);

// dP/du and dP/dv of sphericalUv on the sphere around the axis, at the offset
// `fromCenter` from its centre; dP/dv is zero at the poles.
void sphericalTangents(const Vec3& axis, const Vec3& fromCenter, Vec3& dpdu, Vec3& dpdv);

// dP/du and dP/dv across a triangle whose corners have the given positions
// and texture coordinates (the mapping is affine across it); zero when its
// texture coordinates span no area.
void triangleTangents(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& uv0,
                      const Vec2& uv1, const Vec2& uv2, Vec3& dpdu, Vec3& dpdv);

// The planar mapping of a point by two unit axes in the plane, from an
// origin, in the axes' units.
inline Vec2 planarUv(const Vec3& position, const Vec3& origin, const Vec3& uAxis,
                     const Vec3& vAxis) {
  return {glm::dot(position - origin, uAxis), glm::dot(position - origin, vAxis)};
}

// The planar mapping of a disk (a cap) of the given centre, outward unit
// normal and radius onto the unit square, seen from outside.
Vec2 diskUv(const Vec3& position, const Vec3& center, const Vec3& outwardNormal, float radius);

// dP/du and dP/dv of diskUv.
void diskTangents(const Vec3& outwardNormal, float radius, Vec3& dpdu, Vec3& dpdv);

// The unit axes of the cube mapping on the face of an axis-aligned box whose
// outward normal is `faceNormal` (a signed unit axis): v runs up (+y) on the
// four sides and along -z on the top (+z on the bottom), and u x v is the
// normal, so that seen from outside u grows to the right.
void cubeFaceAxes(const Vec3& faceNormal, Vec3& uAxis, Vec3& vAxis);

// The cube mapping of a point on the face of the box [min, max] with outward
// normal `faceNormal`: each face is the unit square.
Vec2 cubeFaceUv(const Vec3& position, const Vec3& faceNormal, const Vec3& min, const Vec3& max);

// dP/du and dP/dv of cubeFaceUv: the face's axes, as long as its sides.
void cubeFaceTangents(const Vec3& faceNormal, const Vec3& min, const Vec3& max, Vec3& dpdu,
                      Vec3& dpdv);

// The face of an axis-aligned box that a surface of this normal faces most:
// the signed unit axis of the normal's largest component.
Vec3 cubeFaceFacing(const Vec3& normal);

// dP/du and dP/dv along a surface of unit normal `normal` onto which a
// mapping is projected from another surface (a sphere, a cylinder, a plane),
// given that surface's own dP/du and dP/dv (`alongU`, `alongV`, perpendicular
// to each other): the directions in the tangent plane in which u alone and
// v alone grow, at their rates. Zero where the surface runs along the
// projection, so that u and v do not vary apart over it.
void projectedTangents(const Vec3& normal, const Vec3& alongU, const Vec3& alongV, Vec3& dpdu,
                       Vec3& dpdv);

}  // namespace rise
