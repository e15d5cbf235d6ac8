#pragma once

#include <array>

#include "scene/shape.hpp"

namespace rise {

// Where the ray meets the triangle v0, v0 + edge1, v0 + edge2, if that is at
// t in (tMin, tMax): writes t and the barycentric coordinates (u, v) of the
// point v0 + u edge1 + v edge2. Möller and Trumbore, "Fast, Minimum Storage
// Ray-Triangle Intersection", Journal of Graphics Tools 2(1), 1997: Cramer's
// rule on origin + t direction = that point, with the triple products shared.
// Both sides are hit; the edges belong to the triangle, so that no ray slips
// between two triangles of a mesh; a ray in the triangle's plane misses it.
// Inline, because it is the inner loop of every mesh.
inline bool intersectTriangleEdges(const Ray& ray, const Vec3& v0, const Vec3& edge1,
                                   const Vec3& edge2, float tMin, float tMax, float& t,
                                   Vec2& barycentric) {
  const Vec3 p = glm::cross(ray.direction, edge2);
  const float determinant = glm::dot(edge1, p);
  if (determinant == 0.0f) return false;
  const float inverseDeterminant = 1.0f / determinant;
  const Vec3 fromV0 = ray.origin - v0;
  // Negated tests so that a NaN (from a nearly parallel ray) rejects the hit.
  const float u = glm::dot(fromV0, p) * inverseDeterminant;
  if (!(u >= 0.0f && u <= 1.0f)) return false;
  const Vec3 q = glm::cross(fromV0, edge1);
  const float v = glm::dot(ray.direction, q) * inverseDeterminant;
  if (!(v >= 0.0f && u + v <= 1.0f)) return false;
  const float tTriangle = glm::dot(edge2, q) * inverseDeterminant;
  if (!(tTriangle > tMin && tTriangle < tMax)) return false;
  t = tTriangle;
  barycentric = Vec2(u, v);
  return true;
}

// The same for the triangle of corners v0 v1 v2: (u, v) weigh v1 and v2.
inline bool intersectTriangle(const Ray& ray, const Vec3& v0, const Vec3& v1, const Vec3& v2,
                              float tMin, float tMax, float& t, Vec2& barycentric) {
  return intersectTriangleEdges(ray, v0, v1 - v0, v2 - v0, tMin, tMax, t, barycentric);
}

// The unit normal of the triangle v0 v1 v2, on the side from which its
// vertices turn counter-clockwise (right-hand rule).
inline Vec3 windingNormal(const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  return glm::normalize(glm::cross(v1 - v0, v2 - v0));
}

// One triangle; its normal follows the counter-clockwise winding of its
// vertices (right-hand rule).
class Triangle final : public Shape {
 public:
  Triangle(const std::array<Vec3, 3>& vertices, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  bool tessellationIsExact() const override { return true; }
  bool primitiveTriangle(int primitive, std::array<Vec3, 3>& corners) const override;

 private:
  std::array<Vec3, 3> vertices_;
  Vec3 normal_;
};

}  // namespace rise
