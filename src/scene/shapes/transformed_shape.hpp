#pragma once

#include <memory>

#include "scene/shape.hpp"

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

 private:
  Ray objectRay(const Ray& worldRay) const;

  std::unique_ptr<Shape> shape_;
  Mat4 worldFromObject_;
  Mat4 objectFromWorld_;
  Mat3 normalToWorld_;
};

}  // namespace rise
