#pragma once

#include <memory>

#include "scene/shape.hpp"
#include "scene/transform.hpp"

namespace rise {

// A shape placed in the world by an affine transform: rays are taken into the
// shape's own space (without renormalising, so t is the same in both), and its
// normals are brought back with the inverse transpose. It adds no test of its
// own to the counters: the shape inside counts its own.
class TransformedShape final : public Shape {
 public:
  TransformedShape(std::unique_ptr<Shape> shape, const Mat4& worldFromObject);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  SurfacePoint pointAt(const Ray& ray, const Hit& hit) const override;
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;
  // An affine map keeps flat triangles flat.
  bool tessellationIsExact() const override { return shape_->tessellationIsExact(); }

  // The primitives of the shape inside, bounded in the world and tested in
  // the shape's own space.
  int primitiveCount() const override;
  Bounds3 primitiveBounds(int primitive) const override;
  bool intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const override;

 private:
  std::unique_ptr<Shape> shape_;
  AffineMap placement_;
};

}  // namespace rise
