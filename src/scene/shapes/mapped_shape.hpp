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
// tangents at the point, and tessellate the mapping's coordinates at the
// vertices, each triangle mapped as a whole (ProjectedMapping::cornerUvs).
class MappedShape final : public Shape {
 public:
  MappedShape(std::unique_ptr<Shape> shape, const Mapping& mapping);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  // A mapping that turns around an axis is not affine across a triangle:
  // where the shape's triangles are longer than a segment of the circle
  // around the box at this level (the sides of a box, a cylinder's height),
  // each is cut into smaller ones, all by the same number so that
  // neighbours still share their edges' vertices.
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;

  int primitiveCount() const override;
  Bounds3 primitiveBounds(int primitive) const override;
  bool intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const override;
  bool primitiveTriangle(int primitive, std::array<Vec3, 3>& corners) const override;

 private:
  std::unique_ptr<Shape> shape_;
  ProjectedMapping mapping_;
};

}  // namespace rise
