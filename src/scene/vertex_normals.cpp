#include "scene/vertex_normals.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace rise {

namespace {

using PointKey = std::array<float, 3>;

PointKey keyOf(const Vec3& v) { return {v.x, v.y, v.z}; }

// For each vertex, an index shared by all the vertices at its point.
std::vector<int> pointIndices(const std::vector<Vec3>& positions, int& pointCount) {
  std::map<PointKey, int> points;
  std::vector<int> pointOf;
  pointOf.reserve(positions.size());
  for (const Vec3& position : positions)
    pointOf.push_back(
        points.try_emplace(keyOf(position), static_cast<int>(points.size())).first->second);
  pointCount = static_cast<int>(points.size());
  return pointOf;
}

}  // namespace

MeshGeometry withVertexNormals(const MeshGeometry& mesh, float creaseAngleDegrees) {
  // The cross product of two edges is the normal weighted by twice the area.
  std::vector<Vec3> weightedNormals;
  std::vector<Vec3> unitNormals;
  for (const auto& [a, b, c] : mesh.triangles) {
    const Vec3 cross =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    const float length = glm::length(cross);
    weightedNormals.push_back(cross);
    unitNormals.push_back(length > 0.0f ? cross / length : Vec3(0.0f));
  }

  int pointCount = 0;
  const std::vector<int> pointOf = pointIndices(mesh.positions, pointCount);
  std::vector<std::vector<int>> trianglesAround(pointCount);
  for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle)
    for (int vertex : mesh.triangles[triangle])
      trianglesAround[pointOf[vertex]].push_back(static_cast<int>(triangle));

  const float smoothCosine = std::cos(radians(creaseAngleDegrees));
  MeshGeometry smooth;
  std::map<std::pair<int, PointKey>, int> vertexWithNormal;
  for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle) {
    std::array<int, 3> corners;
    for (int corner = 0; corner < 3; ++corner) {
      const int vertex = mesh.triangles[triangle][corner];
      Vec3 sum(0.0f);
      for (int neighbour : trianglesAround[pointOf[vertex]])
        if (glm::dot(unitNormals[triangle], unitNormals[neighbour]) >= smoothCosine)
          sum += weightedNormals[neighbour];
      const float length = glm::length(sum);
      const Vec3 normal = length > 0.0f ? sum / length : unitNormals[triangle];
      const auto [found, added] = vertexWithNormal.try_emplace(
          {vertex, keyOf(normal)}, static_cast<int>(smooth.positions.size()));
      if (added) {
        smooth.positions.push_back(mesh.positions[vertex]);
        smooth.normals.push_back(normal);
        if (!mesh.uvs.empty()) smooth.uvs.push_back(mesh.uvs[vertex]);
      }
      corners[corner] = found->second;
    }
    smooth.triangles.push_back(corners);
  }
  return smooth;
}

}  // namespace rise
