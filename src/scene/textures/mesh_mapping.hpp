// A projected mapping (scene/projected_mapping.hpp) given to a mesh as it
// loads, in its own space, before the object's transform is taken into its
// vertices: the mapping's coordinates replace the mesh's own at every
// corner, each triangle mapped as a whole (ProjectedMapping::cornerUvs). A
// vertex whose triangles give it different coordinates (on both sides of
// the seam, on two faces of a box mapping) becomes one vertex for each, so
// that the ray tracers, which interpolate a mesh's coordinates across each
// triangle, and the visible-surface algorithms see the same ones.
#pragma once

#include <span>

#include "scene/mesh_geometry.hpp"
#include "scene/textures/projected_mapping.hpp"

namespace rise {

// `poses` are the keyframes of one mesh (its triangles the same in each):
// the coordinates are those of the first, around its bounding box, and every
// pose gets them.
void applyMapping(const Mapping& mapping, std::span<MeshGeometry> poses);

}  // namespace rise
