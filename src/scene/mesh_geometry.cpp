#include "scene/mesh_geometry.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
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

// A vertex's attributes as bits, in which any two vertices compare and sort,
// those with coordinates that are not numbers too.
using VertexBits = std::array<std::uint32_t, 8>;

VertexBits bitsOf(const MeshGeometry& geometry, std::size_t vertex) {
  VertexBits bits{};
  const auto put = [&](std::size_t at, float value) {
    bits[at] = std::bit_cast<std::uint32_t>(value);
  };
  for (int axis = 0; axis < 3; ++axis) put(axis, geometry.positions[vertex][axis]);
  if (!geometry.normals.empty())
    for (int axis = 0; axis < 3; ++axis) put(3 + axis, geometry.normals[vertex][axis]);
  if (!geometry.uvs.empty())
    for (int axis = 0; axis < 2; ++axis) put(6 + axis, geometry.uvs[vertex][axis]);
  return bits;
}

}  // namespace

MeshGeometry withIdenticalVerticesJoined(const MeshGeometry& geometry) {
  const std::size_t count = geometry.positions.size();
  std::vector<VertexBits> bits(count);
  for (std::size_t vertex = 0; vertex < count; ++vertex) bits[vertex] = bitsOf(geometry, vertex);
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(bits[a], a) < std::tie(bits[b], b);
  });
  // The first of each run of equal vertices stands for the run.
  std::vector<std::uint32_t> first(count);
  for (std::size_t i = 0; i < count; ++i)
    first[order[i]] =
        i > 0 && bits[order[i]] == bits[order[i - 1]] ? first[order[i - 1]] : order[i];

  MeshGeometry joined;
  std::vector<int> number(count, -1);
  for (std::uint32_t vertex = 0; vertex < count; ++vertex) {
    if (first[vertex] != vertex) continue;
    number[vertex] = static_cast<int>(joined.positions.size());
    joined.positions.push_back(geometry.positions[vertex]);
    if (!geometry.normals.empty()) joined.normals.push_back(geometry.normals[vertex]);
    if (!geometry.uvs.empty()) joined.uvs.push_back(geometry.uvs[vertex]);
  }
  joined.triangles.reserve(geometry.triangles.size());
  for (const auto& [a, b, c] : geometry.triangles)
    joined.triangles.push_back({number[first[a]], number[first[b]], number[first[c]]});
  return joined;
}

MeshGeometry transformed(MeshGeometry geometry, const Mat4& map) {
  const Mat3 normalMap = glm::transpose(glm::inverse(Mat3(map)));
  for (Vec3& position : geometry.positions) position = Vec3(map * glm::vec4(position, 1.0f));
  for (Vec3& normal : geometry.normals) normal = normalizedOrZero(normalMap * normal);
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

std::vector<std::uint32_t> weldedIndices(std::span<const Vec3> positions) {
  const auto lexicographic = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3& p = positions[a];
    const Vec3& q = positions[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  };
  std::vector<std::uint32_t> welded(positions.size());
  std::vector<std::uint32_t> order;
  order.reserve(positions.size());
  std::uint32_t places = 0;
  for (std::uint32_t vertex = 0; vertex < positions.size(); ++vertex) {
    const Vec3& p = positions[vertex];
    if (std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z))
      welded[vertex] = places++;
    else
      order.push_back(vertex);
  }
  std::sort(order.begin(), order.end(), lexicographic);
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || lexicographic(order[i - 1], order[i])) ++places;
    welded[order[i]] = places - 1;
  }
  return welded;
}

}  // namespace rise
