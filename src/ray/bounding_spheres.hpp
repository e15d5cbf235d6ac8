#pragma once

#include <optional>

#include "ray/accelerator.hpp"
#include "ray/ritter_sphere.hpp"

namespace rise {

// Bounding volumes as in the original RISE report: a sphere around each mesh
// (each shape of more than one primitive), found by Ritter's algorithm
// (ritter_sphere.hpp). A ray tests the sphere first, which is cheap, and
// the mesh's triangles only when it passes through the sphere; shapes of one
// primitive are tested directly. The shapes are still tried one after the
// other: the cost per ray still grows with the number of meshes, but a mesh
// off the ray's path costs one sphere test instead of all its triangles.
class BoundingSpheres final : public Accelerator {
 public:
  explicit BoundingSpheres(const std::vector<std::unique_ptr<Shape>>& shapes);

  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const override;
  void visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                      IntersectionCounters& counters) const override;

 private:
  // Whether the ray can meet `shape` at t in (tMin, tMax): always for a
  // shape without a sphere, otherwise when the ray passes through it there.
  bool mayMeet(std::size_t shape, const Ray& ray, float tMin, float tMax,
               IntersectionCounters& counters) const;

  const std::vector<std::unique_ptr<Shape>>& shapes_;
  std::vector<std::optional<BoundingSphere>> spheres_;  // one for each shape, in order
};

}  // namespace rise
