#include "scene/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>

#include "scene/light.hpp"
#include "scene/shape.hpp"

namespace rise {

int Tessellation::addVertex(const SurfaceVertex& vertex) {
  vertices.push_back(vertex);
  return static_cast<int>(vertices.size()) - 1;
}

void Tessellation::addTriangle(int a, int b, int c) {
  if (a == b || b == c || c == a) return;
  triangles.push_back({a, b, c});
}

void Tessellation::addConvexPolygon(std::span<const int> corners) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    addTriangle(corners[0], corners[i], corners[i + 1]);
}

void tessellatePlaced(const Shape& shape, const Mat4& worldFromObject,
                      const TessellationSettings& settings, Tessellation& out) {
  TessellationSettings objectSettings = settings;
  objectSettings.viewpoint = Vec3(glm::inverse(worldFromObject) * glm::vec4(settings.viewpoint, 1.0f));
  shape.tessellate(objectSettings, out);
  const Mat3 normalToWorld = glm::transpose(glm::inverse(Mat3(worldFromObject)));
  for (SurfaceVertex& vertex : out.vertices) {
    vertex.position = Vec3(worldFromObject * glm::vec4(vertex.position, 1.0f));
    vertex.normal = glm::normalize(normalToWorld * vertex.normal);
  }
  if (glm::determinant(Mat3(worldFromObject)) < 0.0f)
    for (auto& triangle : out.triangles) std::swap(triangle[1], triangle[2]);
}

namespace {

// The same number for every vertex at one place: meshes often repeat a corner
// once for each of its texture coordinates.
std::vector<std::uint64_t> weldedIndices(std::span<const Vec3> positions) {
  const auto lexicographic = [&](int a, int b) {
    const Vec3& p = positions[a];
    const Vec3& q = positions[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  };
  std::vector<int> order(positions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), lexicographic);
  std::vector<std::uint64_t> welded(positions.size());
  std::uint64_t place = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && lexicographic(order[i - 1], order[i])) ++place;
    welded[order[i]] = place;
  }
  return welded;
}

}  // namespace

bool enclosesSolid(std::span<const Vec3> positions, std::span<const std::array<int, 3>> triangles) {
  if (triangles.empty()) return false;
  const std::vector<std::uint64_t> welded = weldedIndices(positions);
  const auto edgeKey = [](std::uint64_t from, std::uint64_t to) { return from << 32 | to; };
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& triangle : triangles)
    for (int corner = 0; corner < 3; ++corner)
      edges.push_back(edgeKey(welded[triangle[corner]], welded[triangle[(corner + 1) % 3]]));
  std::sort(edges.begin(), edges.end());
  // Each directed edge once, and its reverse there too.
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
  return std::all_of(edges.begin(), edges.end(), [&](std::uint64_t edge) {
    return std::binary_search(edges.begin(), edges.end(), edgeKey(edge & 0xffffffffu, edge >> 32));
  });
}

int segmentsPerTurn(int level) { return 4 * level; }

std::vector<Vec3> directionsAround(const Vec3& axis, int segments) {
  Vec3 across, acrossToo;
  orthonormalBasis(axis, across, acrossToo);
  std::vector<Vec3> directions;
  directions.reserve(segments);
  for (int i = 0; i < segments; ++i) {
    const float angle = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    directions.push_back(std::cos(angle) * across + std::sin(angle) * acrossToo);
  }
  return directions;
}

}  // namespace rise
