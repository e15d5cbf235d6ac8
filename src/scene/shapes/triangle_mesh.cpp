#include "scene/shapes/triangle_mesh.hpp"

#include <cassert>
#include <utility>

#include "scene/shapes/triangle.hpp"

namespace rise {

TriangleMesh::TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles,
                           int material)
    : Shape(material), vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  for ([[maybe_unused]] const auto& triangle : triangles_)
    for ([[maybe_unused]] int index : triangle)
      assert(index >= 0 && static_cast<std::size_t>(index) < vertices_.size());
}

bool TriangleMesh::intersect(const Ray& ray, float tMin, Hit& hit,
                             IntersectionCounters& counters) const {
  counters.tests += triangles_.size();
  bool found = false;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& [a, b, c] = triangles_[i];
    if (intersectTriangle(ray, vertices_[a], vertices_[b], vertices_[c], tMin, hit.t, hit.t,
                          hit.barycentric)) {
      hit.primitive = static_cast<int>(i);
      found = true;
    }
  }
  if (found) hit.shape = this;
  return found;
}

SurfacePoint TriangleMesh::surfaceAt(const Ray& ray, const Hit& hit) const {
  const auto& [a, b, c] = triangles_[hit.primitive];
  return {ray.at(hit.t), windingNormal(vertices_[a], vertices_[b], vertices_[c])};
}

}  // namespace rise
