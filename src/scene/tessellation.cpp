#include "scene/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "core/warps.hpp"
#include "scene/mesh_geometry.hpp"
#include "scene/shape.hpp"

namespace rise {

void Tessellation::addConvexPolygon(std::span<const int> corners) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    addTriangle(corners[0], corners[i], corners[i + 1]);
}

void tessellatePlaced(const Shape& shape, const Mat4& worldFromObject,
                      const TessellationSettings& settings, Tessellation& out) {
  TessellationSettings objectSettings = settings;
  objectSettings.viewpoint =
      Vec3(glm::inverse(worldFromObject) * glm::vec4(settings.viewpoint, 1.0f));
  shape.tessellate(objectSettings, out);
  const Mat3 normalToWorld = glm::transpose(glm::inverse(Mat3(worldFromObject)));
  for (SurfaceVertex& vertex : out.vertices) {
    vertex.position = Vec3(worldFromObject * glm::vec4(vertex.position, 1.0f));
    vertex.normal = glm::length(vertex.normal) * normalizedOrZero(normalToWorld * vertex.normal);
  }
  out.projectionPlacement = worldFromObject * out.projectionPlacement;
  if (glm::determinant(Mat3(worldFromObject)) < 0.0f)
    for (auto& triangle : out.triangles) std::swap(triangle[1], triangle[2]);
}

namespace {

// Whether each directed edge a -> b between the vertices `vertexOf` maps the
// corners to occurs once, and its reverse b -> a once too. The edges leaving
// each vertex are gathered in one array (counting sort) and sorted by their
// ends, so that a twin of an edge is next to it and its reverse is found by
// binary search among the edges leaving its end: however many edges meet at a
// vertex, the time grows with their number and not with its square.
bool edgesPairUp(std::span<const std::array<int, 3>> triangles,
                 const std::vector<std::uint32_t>& vertexOf) {
  std::vector<std::uint32_t> firstEdge(vertexOf.size() + 1, 0);
  for (const auto& triangle : triangles)
    for (int corner : triangle) ++firstEdge[vertexOf[corner] + 1];
  std::partial_sum(firstEdge.begin(), firstEdge.end(), firstEdge.begin());
  std::vector<std::uint32_t> edgeEnd(firstEdge.back());
  std::vector<std::uint32_t> filled(firstEdge.begin(), firstEdge.end() - 1);
  for (const auto& triangle : triangles)
    for (int corner = 0; corner < 3; ++corner)
      edgeEnd[filled[vertexOf[triangle[corner]]]++] = vertexOf[triangle[(corner + 1) % 3]];

  const auto leaving = [&](std::uint32_t vertex) {
    return std::span<std::uint32_t>(edgeEnd.data() + firstEdge[vertex],
                                    firstEdge[vertex + 1] - firstEdge[vertex]);
  };
  for (std::uint32_t from = 0; from + 1 < firstEdge.size(); ++from)
    std::ranges::sort(leaving(from));
  for (std::uint32_t from = 0; from + 1 < firstEdge.size(); ++from) {
    const std::span<const std::uint32_t> ends = leaving(from);
    if (std::ranges::adjacent_find(ends) != ends.end()) return false;
    for (std::uint32_t end : ends)
      if (!std::ranges::binary_search(leaving(end), from)) return false;
  }
  return true;
}

}  // namespace

bool enclosesSolid(std::span<const Vec3> positions, std::span<const std::array<int, 3>> triangles) {
  if (triangles.empty()) return false;
  std::vector<std::uint32_t> itself(positions.size());
  std::iota(itself.begin(), itself.end(), 0u);
  return edgesPairUp(triangles, itself) || edgesPairUp(triangles, weldedIndices(positions));
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
