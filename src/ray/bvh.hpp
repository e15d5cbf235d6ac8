// A bounding volume hierarchy (S. Rubin and T. Whitted, "A 3-dimensional
// representation for fast rendering of complex scenes", SIGGRAPH 1980; T.
// Kay and J. Kajiya, "Ray Tracing Complex Scenes", SIGGRAPH 1986): boxes
// within boxes, down to a few primitives in each leaf, so that a ray tests
// only the primitives in the boxes it passes through, some log n of them
// instead of n.
//
// Every primitive of every bounded shape is an entry of its own: each
// triangle of a mesh, each sphere or box. Unbounded shapes (planes) are
// tested apart, before the tree. The tree is built binary, by the binned
// surface area heuristic (bvh_builder.hpp), then collapsed into nodes of four
// children whose boxes a ray tests at once (wide_bvh.hpp). The leaves keep
// their triangles (Shape::primitiveTriangle) beside them, as a corner and two
// edges, and their spheres (Shape::primitiveSphere), as a centre and a
// squared radius, and test those themselves, sparing a call into the shape
// (for a mesh, its vertex indices and the edges' subtractions too); other
// primitives are tested by their shapes.
//
// Traversal goes nearest child first: at an inner node the ray tests the
// four children's boxes (slab test, with the ray's inverse direction
// computed once), enters the nearest it meets and keeps the others on a
// small stack, farthest deepest; once a hit nearer than a kept box's entry
// is found, that box is skipped. A packet of coherent rays (the primary rays
// of neighbouring pixels) goes down together: at each node the packet's
// rays test one child's box at once, the packet enters every child any of
// them meets, and only those rays go on in it; each ray keeps its own
// nearest hit, the same as alone (I. Wald, P. Slusallek, C. Benthin and
// M. Wagner, "Interactive Rendering with Coherent Ray Tracing", Computer
// Graphics Forum 20(3), 2001; bvh_packet_traversal.cpp); so does a packet of
// shadow rays towards one light. A shadow ray stops at the first opaque
// primitive it meets. A ray with a NaN or infinite component meets nothing
// (its box tests would find it in every box, empty ones too).
#pragma once

#include <array>
#include <span>

#include "core/left_unfilled.hpp"
#include "ray/accelerator.hpp"
#include "ray/bvh_builder.hpp"
#include "ray/wide_bvh.hpp"

namespace rise {

class NearestHit;

class Bvh final : public Accelerator {
 public:
  // A primitive as a leaf holds it: a triangle or a sphere tested here, on
  // the geometry beside it, or any other tested by its shape.
  enum class Kind : std::uint8_t { Triangle, Sphere, Other };
  struct TriangleEdges {
    Vec3 corner;
    Vec3 edge1;
    Vec3 edge2;
  };
  struct SphereExtent {
    Vec3 center;
    float radiusSquared;
  };
  struct LeafPrimitive {
    PrimitiveRef ref;
    Kind kind;
    union {
      TriangleEdges triangle;
      SphereExtent sphere;
    };
  };

  // Builds on `threads` threads, 0 meaning one per hardware thread.
  explicit Bvh(const std::vector<std::unique_ptr<Shape>>& shapes, int threads = 0);

  bool nearest(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const override;
  void nearestOfPacket(RayPacket& packet, float tMin) const override;
  void visitCrossings(const Ray& ray, float tMin, float tMax, CrossingVisitor& visitor,
                      IntersectionCounters& counters) const override;
  void visitCrossingsOfPacket(
      ShadowRayPacket& packet, float tMin,
      const std::array<CrossingVisitor*, kPacketSize>& visitors) const override;

  std::span<const WideBvhNode> nodes() const { return nodes_; }
  std::span<const LeafPrimitive> primitives() const { return primitives_; }

 private:
  // Walks the boxes that the ray meets at t in (tMin, tMax), nearest first,
  // calling visitLeaf(firstPrimitive, primitiveCount) at each leaf until it
  // returns false. tMax may
  // shrink as the leaves find hits.
  template <typename VisitLeaf>
  void traverse(const Ray& ray, float tMin, const float& tMax, IntersectionCounters& counters,
                VisitLeaf&& visitLeaf) const;
  // Offers the ray's hits on the shapes outside the tree, or on the
  // primitives of a leaf, to its nearest hit; whether any was taken.
  [[gnu::always_inline]] bool offerUnbounded(const Ray& ray, float tMin, NearestHit& nearest,
                                             IntersectionCounters& counters) const;
  [[gnu::always_inline]] bool offerLeaf(std::uint32_t first, std::uint32_t count, const Ray& ray,
                                        float tMin, NearestHit& nearest,
                                        IntersectionCounters& counters) const;
  // Tells the visitor of the ray's crossings of the shapes outside the tree,
  // or of the primitives of a leaf; false once it asks to stop.
  [[gnu::always_inline]] bool crossUnbounded(const Ray& ray, float tMin, float tMax,
                                             CrossingVisitor& visitor,
                                             IntersectionCounters& counters) const;
  [[gnu::always_inline]] bool crossLeaf(std::uint32_t first, std::uint32_t count, const Ray& ray,
                                        float tMin, float tMax, CrossingVisitor& visitor,
                                        IntersectionCounters& counters) const;
  LeafPrimitive leafPrimitive(PrimitiveRef ref) const;
  bool intersectPrimitive(const LeafPrimitive& primitive, const Ray& ray, float tMin, Hit& hit,
                          IntersectionCounters& counters) const;

  std::vector<const Shape*> shapes_;
  std::vector<int> unbounded_;  // the shapes outside the tree
  std::vector<WideBvhNode> nodes_;
  UnfilledVector<LeafPrimitive> primitives_;  // in leaf order, filled by the workers
};

}  // namespace rise
