#pragma once

#include <array>
#include <vector>

#include "scene/mesh_geometry.hpp"
#include "scene/shape.hpp"

namespace rise {

// A mesh animated by keyframes, as a Quake II (MD2) model runs: the keyframes
// hold the same triangles with the vertices in their poses, and a ray at time
// t (0 when the camera's shutter opens, 1 when it closes; an animation's time
// otherwise, see Camera) meets the mesh with every vertex, and its normal,
// moved linearly from one keyframe to the next, the keyframes spread evenly
// over the time from 0 to 1. Rays spread over the shutter interval then blur the motion (Cook,
// Porter and Carpenter, "Distributed Ray Tracing", SIGGRAPH 1984).
class KeyframedMesh final : public Shape {
 public:
  // The two keyframes share their triangles and texture coordinates; only
  // positions and normals differ.
  KeyframedMesh(MeshGeometry start, MeshGeometry end, int material);
  // Two or more keyframes, in the order they are passed through.
  KeyframedMesh(std::vector<MeshGeometry> keyframes, int material);

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

  // The two keyframes around `time`, and how far from the first to the second.
  struct Between {
    const MeshGeometry& from;
    const MeshGeometry& to;
    float fraction;
  };
  Between between(float time) const;

  std::vector<MeshGeometry> keyframes_;  // the first at time 0, the last at time 1
};

}  // namespace rise
