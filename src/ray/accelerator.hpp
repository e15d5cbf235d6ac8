// Acceleration structures: ways for a ray to find what it hits without
// testing every triangle of the scene. A render chooses one (`--accel`) and
// builds it once from the scene's shapes. They all answer the same two
// questions with the same answers, at different costs:
//
//   none     every ray against every shape, as the original RISE did first
//   spheres  Ritter's bounding sphere around each mesh, tested before its triangles
//   bvh      a bounding volume hierarchy over every primitive (the default)
//   embree   Intel's Embree 3, when this build found it
#pragma once

#include <array>
#include <memory>
#include <string_view>
#include <vector>

#include "core/stats.hpp"
#include "render/render_settings.hpp"
#include "scene/shape.hpp"

namespace rise {

// The structures this build can make: Embree only when it was found at build time.
std::vector<Accel> availableAccels();
bool isAvailable(Accel accel);

// Told of each shape that a shadow ray crosses.
class CrossingVisitor {
 public:
  // `shape` indexes the shapes the structure was built from. Returns false
  // to end the search.
  virtual bool crossed(int shape) = 0;

 protected:
  ~CrossingVisitor() = default;
};

// Rays whose nearest hits are wanted together: coherent rays, such as the
// primary rays of neighbouring pixels, pass through mostly the same boxes.
inline constexpr int kPacketSize = 8;
struct RayPacket {
  int size = 0;  // the rays given, from the first
  std::array<Ray, kPacketSize> rays;
  std::array<Hit, kPacketSize> hits;  // as nearest() takes and records each ray's
  std::array<bool, kPacketSize> found{};
  std::array<IntersectionCounters, kPacketSize> costs{};  // each ray's own
};

// Shadow rays whose crossings are wanted together: coherent rays, such as
// those from neighbouring pixels' first hits towards one light.
struct ShadowRayPacket {
  int size = 0;  // the rays given, from the first
  std::array<Ray, kPacketSize> rays;
  std::array<float, kPacketSize> tMax{};                  // each ray's end
  std::array<IntersectionCounters, kPacketSize> costs{};  // each ray's own
};

class Accelerator {
 public:
  virtual ~Accelerator() = default;

  // The nearest hit with t in (tMin, hit.t), recorded in `hit` exactly as the
  // shape's own intersect would record it. Of primitives hit at the very same
  // t (a ray through the edge two triangles share), the first in the scene's
  // order, as brute force finds it (Embree keeps whichever it meets first).
  virtual bool nearest(const Ray& ray, float tMin, Hit& hit,
                       IntersectionCounters& counters) const = 0;

  // The nearest hit of each ray of the packet, the same as nearest() finds.
  // A structure may walk the rays through it together (the BVH does); this
  // one answers them one at a time.
  virtual void nearestOfPacket(RayPacket& packet, float tMin) const;

  // Tells `visitor` of every shape that the ray meets at some t in (tMin,
  // tMax), in any order and possibly more than once (once per primitive
  // met), until the visitor asks to stop: a shadow ray stops at the first
  // opaque shape it meets.
  virtual void visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                              IntersectionCounters& counters) const = 0;

  // Tells visitors[i] of the shapes that ray i of the packet crosses, as
  // visitCrossings() tells them. A structure may walk the rays through it
  // together (the BVH does); this one answers them one at a time.
  virtual void visitCrossingsOfPacket(
      ShadowRayPacket& packet, float tMin,
      const std::array<CrossingVisitor*, kPacketSize>& visitors) const;

  // Adds what the structure has to tell of itself after a render.
  virtual void addStats(Stats& /*stats*/) const {}
};

// Whether the ray meets `shape` at some t in (tMin, tMax): what the
// structures ask of each shape or primitive they find on a shadow ray's way.
inline bool crosses(const Shape& shape, const Ray& ray, float tMin, float tMax,
                    IntersectionCounters& counters) {
  Hit crossing;
  crossing.t = tMax;
  return shape.intersect(ray, tMin, crossing, counters);
}
inline bool crossesPrimitive(const Shape& shape, int primitive, const Ray& ray, float tMin,
                             float tMax, IntersectionCounters& counters) {
  Hit crossing;
  crossing.t = tMax;
  return shape.intersectPrimitive(primitive, ray, tMin, crossing, counters);
}

// Builds the structure `accel` names over `shapes`, which must outlive it,
// on `threads` threads (0: one per core). Throws std::invalid_argument when
// this build does not have it.
std::unique_ptr<Accelerator> buildAccelerator(Accel accel,
                                              const std::vector<std::unique_ptr<Shape>>& shapes,
                                              int threads = 0);

}  // namespace rise
