#include "scene/vertex_normals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rise {

namespace {

// The triangles around each point, in the mesh's order (a triangle with two
// corners at one point is there twice), as one list cut into runs:
// triangles[first[p] .. first[p + 1]) are point p's.
struct TrianglesAround {
  std::vector<int> first;
  std::vector<int> triangles;

  TrianglesAround(const MeshGeometry& mesh, const std::vector<std::uint32_t>& pointOf,
                  std::size_t pointCount)
      : first(pointCount + 1, 0), triangles(3 * mesh.triangles.size()) {
    for (const auto& corners : mesh.triangles)
      for (int vertex : corners) ++first[pointOf[vertex] + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<int> next(first.begin(), first.end() - 1);
    for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle)
      for (int vertex : mesh.triangles[triangle])
        triangles[next[pointOf[vertex]]++] = static_cast<int>(triangle);
  }
};

// The smooth mesh's vertices: each of the mesh's vertices once for every
// normal its corners get, in the order the corners first ask for them.
class VerticesWithNormals {
 public:
  VerticesWithNormals(const MeshGeometry& mesh, MeshGeometry& smooth)
      : mesh_(mesh), smooth_(smooth), firstCopy_(mesh.positions.size(), -1) {
    smooth_.positions.reserve(mesh.positions.size());
    smooth_.normals.reserve(mesh.positions.size());
  }

  // The smooth mesh's vertex for the vertex with this normal.
  int of(int vertex, const Vec3& normal) {
    int last = -1;
    for (int copy = firstCopy_[vertex]; copy >= 0; copy = nextCopy_[copy]) {
      if (smooth_.normals[copy] == normal) return copy;
      last = copy;
    }
    const int added = static_cast<int>(smooth_.positions.size());
    (last < 0 ? firstCopy_[vertex] : nextCopy_[last]) = added;
    nextCopy_.push_back(-1);
    smooth_.positions.push_back(mesh_.positions[vertex]);
    smooth_.normals.push_back(normal);
    if (!mesh_.uvs.empty()) smooth_.uvs.push_back(mesh_.uvs[vertex]);
    return added;
  }

 private:
  const MeshGeometry& mesh_;
  MeshGeometry& smooth_;
  std::vector<int> firstCopy_;  // of each vertex of the mesh, or -1
  std::vector<int> nextCopy_;   // of the same vertex, after each of the smooth mesh's, or -1
};

}  // namespace

MeshGeometry withVertexNormals(const MeshGeometry& mesh, float creaseAngleDegrees) {
  // The cross product of two edges is the normal weighted by twice the area.
  std::vector<Vec3> weightedNormals;
  std::vector<Vec3> unitNormals;
  weightedNormals.reserve(mesh.triangles.size());
  unitNormals.reserve(mesh.triangles.size());
  for (const auto& [a, b, c] : mesh.triangles) {
    const Vec3 cross =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    const float length = glm::length(cross);
    weightedNormals.push_back(cross);
    unitNormals.push_back(length > 0.0f ? cross / length : Vec3(0.0f));
  }

  const std::vector<std::uint32_t> pointOf = weldedIndices(mesh.positions);
  const std::size_t pointCount =
      pointOf.empty() ? 0 : *std::max_element(pointOf.begin(), pointOf.end()) + 1;
  const TrianglesAround around(mesh, pointOf, pointCount);

  const float smoothCosine = std::cos(radians(creaseAngleDegrees));
  MeshGeometry smooth;
  smooth.triangles.reserve(mesh.triangles.size());
  VerticesWithNormals vertices(mesh, smooth);
  for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle) {
    std::array<int, 3> corners;
    for (int corner = 0; corner < 3; ++corner) {
      const int vertex = mesh.triangles[triangle][corner];
      const std::uint32_t point = pointOf[vertex];
      Vec3 sum(0.0f);
      for (int i = around.first[point]; i < around.first[point + 1]; ++i) {
        const int neighbour = around.triangles[i];
        if (glm::dot(unitNormals[triangle], unitNormals[neighbour]) >= smoothCosine)
          sum += weightedNormals[neighbour];
      }
      const float length = glm::length(sum);
      corners[corner] = vertices.of(vertex, length > 0.0f ? sum / length : unitNormals[triangle]);
    }
    smooth.triangles.push_back(corners);
  }
  return smooth;
}

}  // namespace rise
