// Vertex normals for a mesh whose file has none, so that it can be shaded
// smoothly (Gouraud, "Continuous Shading of Curved Surfaces", IEEE
// Transactions on Computers 20(6), 1971): each corner of a triangle gets the
// average of the normals of the triangles around its point, weighted by their
// areas, leaving out those that meet its own triangle at a crease sharper than
// the crease angle, so that a box keeps its edges while a curved surface loses
// its facets.
#pragma once

#include "scene/mesh_geometry.hpp"

namespace rise {

// The mesh with a unit normal at every vertex (zero at the corners of a
// triangle without area). Vertices at the same point smooth together, even
// when the file keeps them apart (at a seam of texture coordinates); corners
// of one vertex that get different normals (along a crease) get vertices of
// their own.
MeshGeometry withVertexNormals(const MeshGeometry& mesh, float creaseAngleDegrees);

}  // namespace rise
