#include "scene/mesh_geometry.hpp"

#include <utility>

namespace rise {

namespace {

// Pads an attribute that one of two merged meshes lacks, so that it stays one
// per vertex.
template <typename T>
void appendAttribute(std::vector<T>& whole, std::size_t wholeVertices, const std::vector<T>& part,
                     std::size_t partVertices) {
  if (whole.empty() && part.empty()) return;
  whole.resize(wholeVertices, T(0.0f));
  if (part.empty())
    whole.resize(wholeVertices + partVertices, T(0.0f));
  else
    whole.insert(whole.end(), part.begin(), part.end());
}

}  // namespace

MeshGeometry transformed(MeshGeometry geometry, const Mat4& map) {
  const Mat3 normalMap = glm::transpose(glm::inverse(Mat3(map)));
  for (Vec3& position : geometry.positions) position = Vec3(map * glm::vec4(position, 1.0f));
  for (Vec3& normal : geometry.normals) {
    const Vec3 mapped = normalMap * normal;
    normal = glm::dot(mapped, mapped) > 0.0f ? glm::normalize(mapped) : Vec3(0.0f);
  }
  if (glm::determinant(Mat3(map)) < 0.0f)
    for (auto& triangle : geometry.triangles) std::swap(triangle[1], triangle[2]);
  return geometry;
}

void append(MeshGeometry& whole, const MeshGeometry& part) {
  const std::size_t wholeVertices = whole.positions.size();
  const std::size_t partVertices = part.positions.size();
  appendAttribute(whole.normals, wholeVertices, part.normals, partVertices);
  appendAttribute(whole.uvs, wholeVertices, part.uvs, partVertices);
  whole.positions.insert(whole.positions.end(), part.positions.begin(), part.positions.end());
  const int offset = static_cast<int>(wholeVertices);
  for (const auto& [a, b, c] : part.triangles)
    whole.triangles.push_back({a + offset, b + offset, c + offset});
}

}  // namespace rise
