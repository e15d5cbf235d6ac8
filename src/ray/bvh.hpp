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
// Built lazily (W. Hunt, W. R. Mark and D. Fussell, "Fast and Lazy Build of
// Acceleration Structures from Scene Hierarchies", IEEE Symposium on
// Interactive Ray Tracing, 2007). The rays of a render may reach a small
// part of a large mesh: a camera sees one side of it, and the hybrid's rays
// only what its mirrors and shadows need. So the build of a larger tree
// stops at subtrees of a few thousand primitives, only gathering each one's
// primitives together; what it does build, the splits above them, is the
// part that sorts every primitive at each level. A subtree is built, the
// same as it would have been at once, the first time a ray enters its box,
// by that ray's thread, while the other rays that reach it meanwhile wait.
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
#include <atomic>
#include <mutex>
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

  // "bvh_subtrees_deferred", the subtrees the build left for the rays, and
  // "bvh_subtrees_built", those of them that rays reached.
  void addStats(Stats& stats) const override;

  // The nodes built so far, the root first.
  std::span<const WideBvhNode> nodes() const { return {nodes_.get(), nodeCount_.load()}; }
  std::span<const LeafPrimitive> primitives() const { return primitives_; }
  // The root node of the child that a node's slot marks kUnbuiltSubtree, its
  // offset `unbuilt`, built first if no ray has reached it yet.
  std::uint32_t subtreeRoot(std::uint32_t unbuilt) const;
  // Builds every subtree no ray has reached yet, on `threads` threads: the
  // whole tree, as the build would have made it at once.
  void buildEverySubtree(int threads) const;

 private:
  struct UnbuiltChild {
    UnbuiltSubtree subtree;
    std::once_flag built;
    std::uint32_t root = 0;  // its node, once built
  };

  // Builds the subtree, puts its nodes after those built so far and fills
  // its leaf primitives; returns its root.
  std::uint32_t build(const UnbuiltSubtree& subtree) const;
  void fillLeafPrimitives(std::uint32_t begin, std::uint32_t end) const;
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
  // The rest grows as rays reach the unbuilt subtrees, which makes no
  // difference to any ray: a subtree is the same whenever it is built.
  // What the subtrees are built from, in leaf order where built.
  mutable UnfilledVector<BuildPrimitive> buildPrimitives_;
  // Room for every node the tree can have, whose pages are brought in as
  // they are filled; nodeCount_ counts those taken.
  std::unique_ptr<WideBvhNode[]> nodes_;
  mutable std::atomic<std::uint32_t> nodeCount_{0};
  mutable std::mutex growing_;  // taken to add nodes
  mutable std::vector<UnbuiltChild> unbuilt_;
  mutable std::atomic<std::uint32_t> builtCount_{0};
  // In leaf order, filled by the workers, and a subtree's by its builder.
  mutable UnfilledVector<LeafPrimitive> primitives_;
};

}  // namespace rise
