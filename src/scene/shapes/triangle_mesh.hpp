#pragma once

#include <array>
#include <vector>

#include "scene/shape.hpp"

namespace rise {

// A mesh of triangles sharing vertices; every triangle is tested for every ray
// (the acceleration structures come in ray/).
class TriangleMesh final : public Shape {
 public:
  TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles, int material);

  bool intersect(const Ray& ray, float tMin, Hit& hit,
                 IntersectionCounters& counters) const override;
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const override;

 private:
  std::vector<Vec3> vertices_;
  std::vector<std::array<int, 3>> triangles_;
};

}  // namespace rise
