#include "scene/shapes/keyframed_mesh.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "scene/shapes/triangle.hpp"
#include "scene/shapes/vertex_attributes.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {

KeyframedMesh::KeyframedMesh(MeshGeometry start, MeshGeometry end, int material)
    : KeyframedMesh(std::vector<MeshGeometry>{std::move(start), std::move(end)}, material) {}

KeyframedMesh::KeyframedMesh(std::vector<MeshGeometry> keyframes, int material)
    : Shape(material), keyframes_(std::move(keyframes)) {
  assert(keyframes_.size() >= 2);
  for ([[maybe_unused]] const MeshGeometry& pose : keyframes_) {
    assert(pose.triangles == keyframes_[0].triangles);
    assert(pose.positions.size() == keyframes_[0].positions.size());
    assert(pose.normals.size() == keyframes_[0].normals.size());
  }
  assert(keyframes_[0].normals.empty() ||
         keyframes_[0].normals.size() == keyframes_[0].positions.size());
  assert(keyframes_[0].uvs.empty() || keyframes_[0].uvs.size() == keyframes_[0].positions.size());
}

KeyframedMesh::Between KeyframedMesh::between(float time) const {
  const int intervals = static_cast<int>(keyframes_.size()) - 1;
  const float along = std::clamp(time, 0.0f, 1.0f) * static_cast<float>(intervals);
  const int from = std::min(static_cast<int>(along), intervals - 1);
  return {keyframes_[from], keyframes_[from + 1], along - static_cast<float>(from)};
}

std::array<Vec3, 3> KeyframedMesh::cornersAt(int triangle, float time) const {
  const auto [from, to, fraction] = between(time);
  std::array<Vec3, 3> corners;
  for (int corner = 0; corner < 3; ++corner) {
    const int vertex = from.triangles[triangle][corner];
    corners[corner] = glm::mix(from.positions[vertex], to.positions[vertex], fraction);
  }
  return corners;
}

SurfacePoint KeyframedMesh::pointOn(int triangle, float time, const Vec2& barycentric) const {
  const auto [v0, v1, v2] = cornersAt(triangle, time);
  SurfacePoint surface(atBarycentric(v0, v1, v2, barycentric), windingNormal(v0, v1, v2));
  const auto [from, to, fraction] = between(time);
  const auto& [a, b, c] = from.triangles[triangle];
  if (!from.normals.empty()) {
    const auto normalAt = [&, &from = from, &to = to, fraction = fraction](int vertex) {
      return glm::mix(from.normals[vertex], to.normals[vertex], fraction);
    };
    surface.shadingNormal =
        interpolatedNormal(surface.normal, normalAt(a), normalAt(b), normalAt(c), barycentric);
    surface.interpolation =
        normalInterpolation({v0, v1, v2}, {normalAt(a), normalAt(b), normalAt(c)}, barycentric);
  }
  if (const std::vector<Vec2>& uvs = from.uvs; !uvs.empty()) {
    surface.uv = atBarycentric(uvs[a], uvs[b], uvs[c], barycentric);
    triangleTangents(v0, v1, v2, uvs[a], uvs[b], uvs[c], surface.dpdu, surface.dpdv);
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
  for (const MeshGeometry& pose : keyframes_)
    for (const Vec3& position : pose.positions) box.grow(position);
  return box;
}

int KeyframedMesh::primitiveCount() const {
  return static_cast<int>(keyframes_[0].triangles.size());
}

Bounds3 KeyframedMesh::primitiveBounds(int triangle) const {
  Bounds3 box;
  for (int vertex : keyframes_[0].triangles[triangle])
    for (const MeshGeometry& pose : keyframes_) box.grow(pose.positions[vertex]);
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
