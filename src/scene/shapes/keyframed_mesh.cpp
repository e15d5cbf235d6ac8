#include "scene/shapes/keyframed_mesh.hpp"

#include <cassert>
#include <utility>

#include "scene/shapes/triangle.hpp"
#include "scene/shapes/vertex_attributes.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {

KeyframedMesh::KeyframedMesh(MeshGeometry start, MeshGeometry end, int material)
    : Shape(material), start_(std::move(start)), end_(std::move(end)) {
  assert(start_.triangles == end_.triangles);
  assert(start_.positions.size() == end_.positions.size());
  assert(start_.normals.size() == end_.normals.size());
  assert(start_.normals.empty() || start_.normals.size() == start_.positions.size());
  assert(start_.uvs.empty() || start_.uvs.size() == start_.positions.size());
}

std::array<Vec3, 3> KeyframedMesh::cornersAt(int triangle, float time) const {
  std::array<Vec3, 3> corners;
  for (int corner = 0; corner < 3; ++corner) {
    const int vertex = start_.triangles[triangle][corner];
    corners[corner] = glm::mix(start_.positions[vertex], end_.positions[vertex], time);
  }
  return corners;
}

SurfacePoint KeyframedMesh::pointOn(int triangle, float time, const Vec2& barycentric) const {
  const auto [v0, v1, v2] = cornersAt(triangle, time);
  SurfacePoint surface(atBarycentric(v0, v1, v2, barycentric), windingNormal(v0, v1, v2));
  const auto& [a, b, c] = start_.triangles[triangle];
  if (!start_.normals.empty()) {
    const auto normalAt = [&](int vertex) {
      return glm::mix(start_.normals[vertex], end_.normals[vertex], time);
    };
    surface.shadingNormal =
        interpolatedNormal(surface.normal, normalAt(a), normalAt(b), normalAt(c), barycentric);
    surface.interpolation =
        normalInterpolation({v0, v1, v2}, {normalAt(a), normalAt(b), normalAt(c)}, barycentric);
  }
  if (!start_.uvs.empty()) {
    surface.uv = atBarycentric(start_.uvs[a], start_.uvs[b], start_.uvs[c], barycentric);
    triangleTangents(v0, v1, v2, start_.uvs[a], start_.uvs[b], start_.uvs[c], surface.dpdu,
                     surface.dpdv);
  }
  return surface;
}

bool KeyframedMesh::intersect(const Ray& ray, float tMin, Hit& hit,
                              IntersectionCounters& counters) const {
  bool found = false;
  for (int triangle = 0; triangle < primitiveCount(); ++triangle)
    found |= intersectPrimitive(triangle, ray, tMin, hit, counters);
  return found;
}

SurfacePoint KeyframedMesh::surfaceAt(const Ray& ray, const Hit& hit) const {
  return pointOn(hit.primitive, ray.time, hit.barycentric);
}

Bounds3 KeyframedMesh::bounds() const {
  Bounds3 box;
  for (const Vec3& position : start_.positions) box.grow(position);
  for (const Vec3& position : end_.positions) box.grow(position);
  return box;
}

int KeyframedMesh::primitiveCount() const { return static_cast<int>(start_.triangles.size()); }

Bounds3 KeyframedMesh::primitiveBounds(int triangle) const {
  Bounds3 box;
  for (int vertex : start_.triangles[triangle]) {
    box.grow(start_.positions[vertex]);
    box.grow(end_.positions[vertex]);
  }
  return box;
}

bool KeyframedMesh::intersectPrimitive(int triangle, const Ray& ray, float tMin, Hit& hit,
                                       IntersectionCounters& counters) const {
  ++counters.tests;
  const auto [v0, v1, v2] = cornersAt(triangle, ray.time);
  if (!intersectTriangle(ray, v0, v1, v2, tMin, hit.t, hit.t, hit.barycentric)) return false;
  hit.shape = this;
  hit.primitive = triangle;
  return true;
}

void KeyframedMesh::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  static const std::array<Vec2, 3> kCornerBarycentrics{Vec2(0.0f), Vec2(1.0f, 0.0f),
                                                       Vec2(0.0f, 1.0f)};
  for (int triangle = 0; triangle < primitiveCount(); ++triangle) {
    std::array<int, 3> corners;
    for (int corner = 0; corner < 3; ++corner) {
      const SurfacePoint point = pointOn(triangle, settings.time, kCornerBarycentrics[corner]);
      corners[corner] = out.addVertex({point.position, point.shadingNormal, point.uv});
    }
    out.addTriangle(corners[0], corners[1], corners[2], triangle);
  }
}

}  // namespace rise
