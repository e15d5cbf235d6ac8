// Intel Embree 3 (I. Wald, S. Woop, C. Benthin, G. S. Johnson and M. Ernst,
// "Embree: A Kernel Framework for Efficient CPU Ray Tracing", ACM
// Transactions on Graphics 33(4), 2014) as an acceleration structure, so that
// RISE's own BVH can be compared with the industry's: wide BVHs traversed
// with SIMD instructions.
//
// Shapes made of triangles that stand still are given to Embree as triangle
// geometry, which it intersects itself; every other bounded shape is user
// geometry, whose primitives Embree bounds and calls back into
// Shape::intersectPrimitive to test. Unbounded shapes (planes) are tested
// apart. The nearest triangle Embree finds is tested once more by RISE's
// own triangle test, so that t and the barycentric coordinates are the same
// bits as every other structure's. Shadow rays go through Embree's occlusion
// query, with a filter that tells the crossings to the visitor.
//
// The counters see only the tests RISE makes: user geometry, and the one
// test that confirms Embree's nearest triangle; Embree's own box and
// triangle tests are not counted, and no nodes are. Of two triangles hit at
// the very same t, Embree keeps the one it meets first, which may not be the
// one brute force keeps: on rare pixels the image may differ from the other
// structures' by a shade.
#pragma once

#include <embree3/rtcore.h>

#include "ray/accelerator.hpp"

namespace rise {

struct EmbreeFunctions;

// Embree's library is loaded when the first accelerator of it is made
// (core/shared_library.hpp); a build without Embree has no such class.
class EmbreeAccelerator final : public Accelerator {
 public:
  // Builds on `threads` threads (0: one per core). Throws
  // std::runtime_error when Embree's library cannot be loaded or Embree
  // reports an error.
  EmbreeAccelerator(const std::vector<std::unique_ptr<Shape>>& shapes, int threads);
  ~EmbreeAccelerator() override;
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const override;
  void visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                      IntersectionCounters& counters) const override;

 private:
  void addTriangles(unsigned int shape);
  void addUserGeometry(unsigned int shape);

  const EmbreeFunctions& embree_;
  const std::vector<std::unique_ptr<Shape>>& shapes_;
  std::vector<int> unbounded_;
  std::vector<bool> isTriangles_;  // for each shape: given to Embree as triangles
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace rise
