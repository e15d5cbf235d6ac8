#pragma once

#include <array>

#include "scene/mesh_geometry.hpp"
#include "scene/shape.hpp"

namespace rise {

// A mesh animated by keyframes, as a Quake II (MD2) model runs: two keyframes
// hold the same triangles with the vertices in two poses, and a ray at time t
// (0 when the camera's shutter opens, 1 when it closes) meets the mesh with
// every vertex, and its normal, moved linearly from its first pose to its
// second. Rays spread over the shutter interval then blur the motion (Cook,
// Porter and Carpenter, "Distributed Ray Tracing", SIGGRAPH 1984).
class KeyframedMesh final : public Shape {
 public:
  // The two keyframes share their triangles and texture coordinates; only
  // positions and normals differ.
  KeyframedMesh(MeshGeometry start, MeshGeometry end, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;

  // Each triangle is a primitive. A vertex moves in a straight line, so a
  // triangle stays inside the box around its corners in both keyframes.
  int primitiveCount() const override;
  Bounds3 primitiveBounds(int triangle) const override;
  bool intersectPrimitive(int triangle, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const override;

  // The pose at settings.time, each triangle with corners of its own that
  // carry the same normals the ray tracer shades with.
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;

 private:
  std::array<Vec3, 3> cornersAt(int triangle, float time) const;
  // The surface at the point of `triangle` with these barycentric coordinates.
  SurfacePoint pointOn(int triangle, float time, const Vec2& barycentric) const;

  MeshGeometry start_;  // the pose at time 0
  MeshGeometry end_;    // the pose at time 1
};

}  // namespace rise
