#include "scene/textures/mesh_mapping.hpp"

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace rise {

namespace {

// The attribute of each new vertex, taken from the old vertex it copies.
template <typename T>
std::vector<T> copiedFor(const std::vector<T>& values, const std::vector<int>& copies) {
  if (values.empty()) return values;
  std::vector<T> copied;
  copied.reserve(copies.size());
  for (int source : copies) copied.push_back(values[source]);
  return copied;
}

}  // namespace

void applyMapping(const Mapping& mapping, std::span<MeshGeometry> poses) {
  const MeshGeometry& first = poses.front();
  Bounds3 bounds;
  for (const Vec3& position : first.positions) bounds.grow(position);
  const ProjectedMapping projected(mapping, bounds);
  // Each new vertex: the old one it copies and its coordinates.
  std::vector<int> copies;
  std::vector<Vec2> uvs;
  std::map<std::pair<int, std::array<float, 2>>, int> vertexOf;
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(first.triangles.size());
  for (const auto& triangle : first.triangles) {
    const std::array<Vec2, 3> corners = projected.cornerUvs(
        {first.positions[triangle[0]], first.positions[triangle[1]], first.positions[triangle[2]]});
    std::array<int, 3> mapped;
    for (int corner = 0; corner < 3; ++corner) {
      const auto [found, isNew] =
          vertexOf.try_emplace({triangle[corner], {corners[corner].x, corners[corner].y}},
                               static_cast<int>(copies.size()));
      if (isNew) {
        copies.push_back(triangle[corner]);
        uvs.push_back(corners[corner]);
      }
      mapped[corner] = found->second;
    }
    triangles.push_back(mapped);
  }
  for (MeshGeometry& pose : poses) {
    pose.positions = copiedFor(pose.positions, copies);
    pose.normals = copiedFor(pose.normals, copies);
    pose.uvs = uvs;
    pose.triangles = triangles;
  }
}

}  // namespace rise
