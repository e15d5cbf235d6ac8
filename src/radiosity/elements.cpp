#include "radiosity/elements.hpp"

#include <algorithm>
#include <cmath>

#include "scene/mesh_geometry.hpp"
#include "scene/shapes/triangle_mesh.hpp"

namespace rise {

namespace {

// The vertex at (i, j) of the face's n x n grid: a + (b - a) i / n + (c - a) j / n.
SurfaceVertex gridVertex(const std::array<const SurfaceVertex*, 3>& corners, int i, int j, int n) {
  const float u = static_cast<float>(i) / n, v = static_cast<float>(j) / n, w = 1.0f - u - v;
  SurfaceVertex vertex;
  vertex.position = w * corners[0]->position + u * corners[1]->position + v * corners[2]->position;
  vertex.normal =
      normalizedOrZero(w * corners[0]->normal + u * corners[1]->normal + v * corners[2]->normal);
  vertex.uv = w * corners[0]->uv + u * corners[1]->uv + v * corners[2]->uv;
  return vertex;
}

void addElement(ElementMesh& mesh, const SceneFace& face, std::array<int, 3> vertices) {
  const std::vector<SurfaceVertex>& all = mesh.triangles.vertices;
  const Vec3 a = all[vertices[0]].position, b = all[vertices[1]].position,
             c = all[vertices[2]].position;
  const Vec3 cross = glm::cross(b - a, c - a);
  const float area = 0.5f * glm::length(cross);
  if (!(area > 0.0f)) return;
  mesh.triangles.faces.push_back({vertices, face.shape, face.primitive, face.material, false});
  mesh.elements.push_back({vertices, (a + b + c) / 3.0f, cross / (2.0f * area), area, face.material,
                           face.shape, !face.cullable});
}

// The face's n x n triangles: rows of (i, j) with i + j <= n, each square of
// the grid two triangles but along the diagonal edge, one.
void cutFace(const TessellatedScene& tessellated, const SceneFace& face, int n, ElementMesh& mesh) {
  const std::array<const SurfaceVertex*, 3> corners = {&tessellated.vertices[face.vertices[0]],
                                                       &tessellated.vertices[face.vertices[1]],
                                                       &tessellated.vertices[face.vertices[2]]};
  std::vector<SurfaceVertex>& vertices = mesh.triangles.vertices;
  const int first = static_cast<int>(vertices.size());
  // Row j holds n + 1 - j vertices; rowStart(j) is the first's index.
  const auto rowStart = [&](int j) { return first + j * (n + 1) - j * (j - 1) / 2; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) vertices.push_back(gridVertex(corners, i, j, n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      const int at = rowStart(j) + i, above = rowStart(j + 1) + i;
      addElement(mesh, face, {at, at + 1, above});
      if (i + j + 1 < n) addElement(mesh, face, {at + 1, above + 1, above});
    }
}

}  // namespace

std::array<Vec3, 3> cornersOf(const std::vector<SurfaceVertex>& vertices,
                              const std::array<int, 3>& indices) {
  return {vertices[indices[0]].position, vertices[indices[1]].position,
          vertices[indices[2]].position};
}

float longestSide(const std::array<Vec3, 3>& corners) {
  return std::max({glm::length(corners[1] - corners[0]), glm::length(corners[2] - corners[1]),
                   glm::length(corners[0] - corners[2])});
}

int cutsOfFace(const std::array<Vec3, 3>& corners, float largestSide) {
  const float cuts = std::ceil(longestSide(corners) / largestSide);
  if (!(cuts >= 1.0f)) return 1;
  return static_cast<int>(std::min(cuts, static_cast<float>(kMostCutsOfAFace)));
}

Scene elementsAsScene(const Scene& scene, const ElementMesh& mesh) {
  Scene elements;
  elements.materials = scene.materials;
  std::vector<MeshGeometry> byMaterial(scene.materials.size());
  for (const Element& element : mesh.elements) {
    MeshGeometry& geometry = byMaterial[static_cast<std::size_t>(element.material)];
    const int first = static_cast<int>(geometry.positions.size());
    for (const int vertex : element.vertices)
      geometry.positions.push_back(mesh.triangles.vertices[vertex].position);
    geometry.triangles.push_back({first, first + 1, first + 2});
  }
  for (std::size_t m = 0; m < byMaterial.size(); ++m)
    if (!byMaterial[m].triangles.empty())
      elements.shapes.push_back(
          std::make_unique<TriangleMesh>(std::move(byMaterial[m]), static_cast<int>(m)));
  return elements;
}

ElementMesh meshElements(const TessellatedScene& tessellated, float largestSide) {
  ElementMesh mesh;
  mesh.triangles.projections = tessellated.projections;
  for (const SceneFace& face : tessellated.faces)
    cutFace(tessellated, face,
            cutsOfFace(cornersOf(tessellated.vertices, face.vertices), largestSide), mesh);
  return mesh;
}

std::uint64_t elementCount(const TessellatedScene& tessellated, float largestSide) {
  std::uint64_t count = 0;
  for (const SceneFace& face : tessellated.faces) {
    const auto n = static_cast<std::uint64_t>(
        cutsOfFace(cornersOf(tessellated.vertices, face.vertices), largestSide));
    count += n * n;
  }
  return count;
}

std::array<std::vector<Color>, 2> vertexLight(const ElementMesh& mesh,
                                              const std::vector<TwoSides>& elementLight) {
  const std::vector<SurfaceVertex>& vertices = mesh.triangles.vertices;
  std::vector<Vec3> positions;
  positions.reserve(vertices.size());
  for (const SurfaceVertex& vertex : vertices) positions.push_back(vertex.position);
  const std::vector<std::uint32_t> point = weldedIndices(positions);
  // The elements around each point, as a list per point.
  const std::uint32_t points =
      point.empty() ? 0 : *std::max_element(point.begin(), point.end()) + 1;
  std::vector<std::vector<int>> around(points);
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    for (const int vertex : mesh.elements[e].vertices) around[point[vertex]].push_back(e);
  std::vector<int> materialOf(vertices.size(), -1);  // of the faces drawn with the vertex
  for (const SceneFace& face : mesh.triangles.faces)
    for (const int vertex : face.vertices) materialOf[vertex] = face.material;

  constexpr float kSameWay = 0.7071f;  // cos 45 degrees
  std::array<std::vector<Color>, 2> light;
  for (int side : {kFrontSide, kBackSide}) light[side].assign(vertices.size(), Color(0.0f));
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Vec3& normal = vertices[v].normal;
    const bool knowsItsWay = glm::dot(normal, normal) > 0.0f;
    TwoSides sum{Color(0.0f), Color(0.0f)};
    float weight = 0.0f;
    for (const int e : around[point[v]]) {
      const Element& element = mesh.elements[e];
      if (element.material != materialOf[v]) continue;
      const float agreement = glm::dot(element.normal, normal);
      if (knowsItsWay && std::abs(agreement) < kSameWay) continue;
      // An element turned the other way shows its back on the vertex's front.
      const bool turned = agreement < 0.0f;
      for (int side : {kFrontSide, kBackSide})
        sum[side] += element.area * elementLight[e][turned ? 1 - side : side];
      weight += element.area;
    }
    if (weight > 0.0f)
      for (int side : {kFrontSide, kBackSide}) light[side][v] = sum[side] / weight;
  }
  return light;
}

}  // namespace rise
