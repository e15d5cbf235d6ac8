#pragma once

#include <array>
#include <vector>

#include "scene/mesh_geometry.hpp"
#include "scene/shape.hpp"

namespace rise {

// A mesh of triangles sharing vertices; every triangle is tested for every ray
// (the acceleration structures come in ray/). When the model gives its
// vertices normals and texture coordinates, they are interpolated across each
// triangle: the normals for smooth shading, the coordinates for textures.
class TriangleMesh final : public Shape {
 public:
  TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles, int material);
  TriangleMesh(MeshGeometry geometry, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  bool tessellationIsExact() const override { return true; }

  // Each triangle is a primitive, so that an acceleration structure can
  // bound and test the triangles one by one.
  int primitiveCount() const override;
  Bounds3 primitiveBounds(int triangle) const override;
  bool intersectPrimitive(int triangle, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const override;
  bool primitiveTriangle(int triangle, std::array<Vec3, 3>& corners) const override;

 private:
  std::vector<Vec3> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Vec3> normals_;  // one per vertex, or none
  std::vector<Vec2> uvs_;      // one per vertex, or none
  // Found once, where the mesh is made, since its triangles never change:
  // their bounds, and whether they close around a solid.
  Bounds3 bounds_;
  bool enclosesSolid_;
};

}  // namespace rise
