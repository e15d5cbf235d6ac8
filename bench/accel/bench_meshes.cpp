#include "bench_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "io/mesh_file.hpp"
#include "scene/camera.hpp"
#include "scene/shapes/triangle_mesh.hpp"

namespace rise::bench {
namespace {

struct Polyhedron {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
};

Polyhedron icosahedron() {
  const float phi = 0.5f * (1.0f + std::sqrt(5.0f));
  return {{{-1, phi, 0},
           {1, phi, 0},
           {-1, -phi, 0},
           {1, -phi, 0},
           {0, -1, phi},
           {0, 1, phi},
           {0, -1, -phi},
           {0, 1, -phi},
           {phi, 0, -1},
           {phi, 0, 1},
           {-phi, 0, -1},
           {-phi, 0, 1}},
          {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
           {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
           {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}}};
}

// Each triangle becomes four, through the midpoints of its edges; an edge's
// midpoint is made once and shared by the two triangles beside it.
Polyhedron subdivided(const Polyhedron& coarse) {
  Polyhedron fine{coarse.vertices, {}};
  std::map<std::pair<int, int>, int> midpoints;
  const auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [entry, added] = midpoints.try_emplace(key, static_cast<int>(fine.vertices.size()));
    if (added) fine.vertices.push_back(0.5f * (fine.vertices[a] + fine.vertices[b]));
    return entry->second;
  };
  for (const auto& [a, b, c] : coarse.faces) {
    const int ab = midpoint(a, b);
    const int bc = midpoint(b, c);
    const int ca = midpoint(c, a);
    fine.faces.insert(fine.faces.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
  }
  return fine;
}

float bumpiness(const Vec3& direction) {
  return 1.0f + 0.15f * std::sin(7.0f * direction.x) * std::sin(9.0f * direction.y) *
                    std::sin(5.0f * direction.z);
}

}  // namespace

std::unique_ptr<Shape> bumpyIcosphere(int subdivisions) {
  Polyhedron mesh = icosahedron();
  for (int i = 0; i < subdivisions; ++i) mesh = subdivided(mesh);
  for (Vec3& vertex : mesh.vertices) {
    const Vec3 direction = glm::normalize(vertex);
    vertex = bumpiness(direction) * direction;
  }
  return std::make_unique<TriangleMesh>(std::move(mesh.vertices), std::move(mesh.faces), 0);
}

std::unique_ptr<Shape> stanfordBunny() {
  return std::make_unique<TriangleMesh>(
      loadMeshFile(std::string(RISE_SOURCE_DIR) +
                   "/examples/models/stanford-bunny/stanford-bunny.obj"),
      0);
}

std::vector<Ray> cameraRays(const Shape& shape, int width, int height) {
  const Bounds3 box = shape.bounds();
  const float size = glm::length(box.extent());
  Camera camera;
  camera.lookAt = box.centre();
  camera.position = box.centre() + 0.8f * size * glm::normalize(Vec3(0.5f, 0.4f, 1.0f));
  camera.up = Vec3(0.0f, 1.0f, 0.0f);
  camera.fovDegrees = 45.0f;
  const ViewFrame view(camera, width, height);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rays.push_back(view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  return rays;
}

}  // namespace rise::bench
