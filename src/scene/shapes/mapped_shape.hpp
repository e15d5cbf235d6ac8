#pragma once

#include <memory>

#include "scene/shape.hpp"
#include "scene/textures/projected_mapping.hpp"

namespace rise {

// A shape that wears a projected mapping (scene/projected_mapping.hpp)
// around its bounding box instead of its own texture coordinates. It wraps
// the shape in the shape's own space, inside the TransformedShape that
// places it, so that the texture moves with the object. Rays meet the shape
// inside as they would; surfaceAt gives the mapping's coordinates and
// tangents at the point, and the tessellation carries the mapping itself
// (Tessellation::projection), its vertices the coordinates there.
class MappedShape final : public Shape {
 public:
  MappedShape(std::unique_ptr<Shape> shape, const Mapping& mapping);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  SurfacePoint pointAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;
  bool tessellationIsExact() const override { return shape_->tessellationIsExact(); }

  int primitiveCount() const override;
  Bounds3 primitiveBounds(int primitive) const override;
  bool intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const override;
  bool primitiveTriangle(int primitive, std::array<Vec3, 3>& corners) const override;
  bool primitiveSphere(int primitive, Vec3& center, float& radiusSquared) const override;

 private:
  std::unique_ptr<Shape> shape_;
  ProjectedMapping mapping_;
};

}  // namespace rise
