#pragma once

#include <memory>

#include "scene/shape.hpp"
#include "scene/transform.hpp"

namespace rise {

// A shape that moves while the camera's shutter is open, for motion blur
// (Cook, Porter & Carpenter 1984). Its placement goes linearly from `open`, at
// ray time 0 (the shutter opening), to `close`, at ray time 1 (the shutter
// closing), and each ray meets the shape where it is at the ray's time.
class MovingShape final : public Shape {
 public:
  MovingShape(std::unique_ptr<Shape> shape, const TransformSpec& open, const TransformSpec& close);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;
  SurfacePoint pointAt(const Ray& ray, const Hit& hit) const override;
  // The box that holds the shape throughout the shutter interval.
  Bounds3 bounds() const override;
  void tessellate(const TessellationSettings& settings, Tessellation& out) const override;
  std::uint64_t tessellatedTriangles(int level) const override;

 private:
  AffineMap placementAt(float time) const;

  std::unique_ptr<Shape> shape_;
  TransformSpec open_;
  TransformSpec close_;
};

}  // namespace rise
