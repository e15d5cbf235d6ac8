// Bump mapping (J. F. Blinn, "Simulation of Wrinkled Surfaces", SIGGRAPH
// 1978): the surface is imagined moved along its normal N by a height F(u, v)
// read from a texture, and shaded with the normal of that moved surface,
//
//   N' = N + Fu (N x Pv) + Fv (Pu x N)      (N of unit length here)
//
// where Pu and Pv are dP/du and dP/dv and Fu, Fv the height's derivatives,
// taken by central differences. N' is scaled by |Pu x Pv| so that the slope
// does not depend on how the texture is stretched. The surface itself does
// not move: intersections, silhouettes and shadows stay those of the smooth
// surface, only the shading normal tilts.
//
// Normal mapping: the shading normal read from an image in tangent space,
// its red, green and blue (linear, in [0, 1]) mapping to -1..1 along the
// directions in which u grows, in which v grows (both made perpendicular to
// the normal) and along the normal, so that the flat colour (0.5, 0.5, 1)
// leaves the normal as it is. As with a bump map, only shading sees the
// tilted normal.
#pragma once

#include "scene/textures/bump_map.hpp"
#include "scene/textures/normal_map.hpp"

namespace rise {

// The shading normal of the bumped surface at `surface`, on the side of its
// shading normal. A surface without tangents (Pu x Pv = 0) keeps its normal.
Vec3 bumped(const BumpMap& bump, const SurfacePoint& surface);

// The shading normal the map gives at `surface`; a surface without tangents
// (dpdu = 0) keeps its own.
Vec3 normalMapped(const NormalMap& map, const SurfacePoint& surface);

}  // namespace rise
