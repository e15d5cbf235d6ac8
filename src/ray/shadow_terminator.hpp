// The shadow terminator of smooth-shaded meshes, and Hanika's remedy
// (J. Hanika, "Hacking the Shadow Terminator", Ray Tracing Gems II, 2021).
//
// A mesh shaded smoothly is lit by its interpolated normals, as if it were
// the curved surface they describe; but a shadow ray leaves from the flat
// triangle, which lies below that surface wherever the mesh is convex. Near
// the line where the light grazes the surface (the terminator) a triangle
// can face the light by its normals while its neighbours, rising above the
// flat plane, stand between it and the light: the shadow ray hits them, and
// the light's edge runs along the triangles in jagged steps that the smooth
// shading does not explain.
//
// Hanika lifts the shadow ray's origin onto a curved surface through the
// corners: each corner's tangent plane (through the corner, across its
// normal) holds the point projected onto it where the point lies below it,
// and the projections, blended by the point's barycentric coordinates, give
// the new origin. On a convex patch it rises above the flat triangle, as
// the surface the normals describe does; on a concave one, where the point
// lies above every tangent plane, it stays.
//
// The light's side is the smooth surface's too: a light behind the flat
// triangle but in front of the interpolated normal lights the point, as it
// does in the shading of the visible-surface algorithms, else the terminator
// would follow the triangles' edges all the same.
#pragma once

#include <optional>

#include "core/ray.hpp"
#include "scene/shape.hpp"

namespace rise {

// The point a shadow ray leaves from: Hanika's lifted point where the
// surface interpolates normals and the lift goes to the side `sideNormal`
// faces (the side the ray leaves from), else the surface's own point.
Vec3 shadowRayOrigin(const SurfacePoint& surface, const Vec3& sideNormal);

// The shadow ray towards a light in direction `toLight` from that point,
// set off the surface by kRayEpsilon; none where the light lies behind the
// surface, on the other side than `sideNormal` of the interpolated normal
// (of the surface's own, where it interpolates none).
std::optional<Ray> shadowRay(const SurfacePoint& surface, const Vec3& sideNormal,
                             const Vec3& toLight, float time);

}  // namespace rise
