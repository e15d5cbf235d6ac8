#include "scene/shapes/triangle_mesh.hpp"

#include <cassert>
#include <utility>

#include "scene/shapes/triangle.hpp"
#include "scene/shapes/vertex_attributes.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {

TriangleMesh::TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles,
                           int material)
    : TriangleMesh(MeshGeometry{std::move(vertices), {}, {}, std::move(triangles)}, material) {}

TriangleMesh::TriangleMesh(MeshGeometry geometry, int material)
    : Shape(material),
      vertices_(std::move(geometry.positions)),
      triangles_(std::move(geometry.triangles)),
      normals_(std::move(geometry.normals)),
      uvs_(std::move(geometry.uvs)),
      enclosesSolid_(enclosesSolid(vertices_, triangles_)) {
  assert(normals_.empty() || normals_.size() == vertices_.size());
  assert(uvs_.empty() || uvs_.size() == vertices_.size());
  for ([[maybe_unused]] const auto& triangle : triangles_)
    for ([[maybe_unused]] int index : triangle)
      assert(index >= 0 && static_cast<std::size_t>(index) < vertices_.size());
  for (int triangle = 0; triangle < primitiveCount(); ++triangle)
    bounds_.grow(primitiveBounds(triangle));
}

bool TriangleMesh::intersect(const Ray& ray, float tMin, Hit& hit,
                             IntersectionCounters& counters) const {
  bool found = false;
  for (int triangle = 0; triangle < primitiveCount(); ++triangle)
    found |= intersectPrimitive(triangle, ray, tMin, hit, counters);
  return found;
}

SurfacePoint TriangleMesh::surfaceAt(const Ray& ray, const Hit& hit) const {
  const auto& [a, b, c] = triangles_[hit.primitive];
  SurfacePoint surface(ray.at(hit.t), windingNormal(vertices_[a], vertices_[b], vertices_[c]));
  if (!normals_.empty()) {
    surface.shadingNormal =
        interpolatedNormal(surface.normal, normals_[a], normals_[b], normals_[c], hit.barycentric);
    surface.interpolation =
        normalInterpolation({vertices_[a], vertices_[b], vertices_[c]},
                            {normals_[a], normals_[b], normals_[c]}, hit.barycentric);
  }
  if (!uvs_.empty()) {
    surface.uv = atBarycentric(uvs_[a], uvs_[b], uvs_[c], hit.barycentric);
    triangleTangents(vertices_[a], vertices_[b], vertices_[c], uvs_[a], uvs_[b], uvs_[c],
                     surface.dpdu, surface.dpdv);
  }
  return surface;
}

Bounds3 TriangleMesh::bounds() const { return bounds_; }

int TriangleMesh::primitiveCount() const { return static_cast<int>(triangles_.size()); }

Bounds3 TriangleMesh::primitiveBounds(int triangle) const {
  Bounds3 box;
  for (int index : triangles_[triangle]) box.grow(vertices_[index]);
  return box;
}

bool TriangleMesh::intersectPrimitive(int triangle, const Ray& ray, float tMin, Hit& hit,
                                      IntersectionCounters& counters) const {
  ++counters.tests;
  const auto& [a, b, c] = triangles_[triangle];
  if (!intersectTriangle(ray, vertices_[a], vertices_[b], vertices_[c], tMin, hit.t, hit.t,
                         hit.barycentric))
    return false;
  hit.shape = this;
  hit.primitive = triangle;
  return true;
}

bool TriangleMesh::primitiveTriangle(int triangle, std::array<Vec3, 3>& corners) const {
  for (int corner = 0; corner < 3; ++corner)
    corners[corner] = vertices_[triangles_[triangle][corner]];
  return true;
}

// With normals at its vertices, the mesh as it is, its triangles sharing
// their corners; without, each triangle with corners of its own, all three
// with its flat normal, as the ray tracer shades it. The vertices are
// written in place, into arrays made at their full sizes, not added one by
// one: a large mesh's copy is most of its tessellation's time.
void TriangleMesh::tessellate(const TessellationSettings&, Tessellation& out) const {
  const auto uvAt = [&](int vertex) { return uvs_.empty() ? Vec2(0.0f) : uvs_[vertex]; };
  out.triangles.reserve(triangles_.size());
  out.primitives.reserve(triangles_.size());
  if (!normals_.empty()) {
    out.vertices.resize(vertices_.size());
    for (int i = 0; i < static_cast<int>(vertices_.size()); ++i)
      out.vertices[i] = {vertices_[i], normals_[i], uvAt(i)};
    for (int triangle = 0; triangle < primitiveCount(); ++triangle) {
      const auto& [a, b, c] = triangles_[triangle];
      out.addTriangle(a, b, c, triangle);
    }
  } else {
    out.vertices.resize(3 * triangles_.size());
    for (int triangle = 0; triangle < primitiveCount(); ++triangle) {
      const auto& corners = triangles_[triangle];
      const Vec3 normal =
          windingNormal(vertices_[corners[0]], vertices_[corners[1]], vertices_[corners[2]]);
      const int first = 3 * triangle;
      for (int corner = 0; corner < 3; ++corner)
        out.vertices[first + corner] = {vertices_[corners[corner]], normal, uvAt(corners[corner])};
      out.addTriangle(first, first + 1, first + 2, triangle);
    }
  }
  out.enclosesSolid = enclosesSolid_;
}

}  // namespace rise
