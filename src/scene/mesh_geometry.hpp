// The data of a triangle mesh as files and scenes give it: shared vertices,
// each with a unit normal and texture coordinates when the model has them, and
// triangles as triples of vertex indices.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.hpp"

namespace rise {

struct MeshGeometry {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // one per position, or none; a zero normal is unknown
  std::vector<Vec2> uvs;      // one per position, or none
  std::vector<std::array<int, 3>> triangles;
};

// The geometry moved by an affine map: positions by it, normals by its
// inverse transpose. A map that mirrors reverses each triangle's winding, so
// that the winding still turns counter-clockwise around the side the normals
// face.
MeshGeometry transformed(MeshGeometry geometry, const Mat4& map);

// Appends `part` to `whole`, its indices shifted past the vertices already
// there. Normals and texture coordinates that only one side has are padded
// with zeros.
void append(MeshGeometry& whole, const MeshGeometry& part);

// The geometry with the vertices that are the same in every attribute
// (position, normal and texture coordinates, bit for bit) made one, numbered
// in the order in which they first appear; the triangles keep their order.
// Some readers give each corner of each face a vertex of its own (Assimp's
// PLY and OBJ readers do).
MeshGeometry withIdenticalVerticesJoined(const MeshGeometry& geometry);

// For each vertex, a number shared by all the vertices at its point (meshes
// often repeat a corner once for each of its texture coordinates), from 0 up
// without gaps. A vertex with a coordinate that is not a number, which no
// order can place, is a point of its own.
std::vector<std::uint32_t> weldedIndices(std::span<const Vec3> positions);

}  // namespace rise
