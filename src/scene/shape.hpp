#pragma once

#include <cstdint>

#include "core/bounds.hpp"
#include "core/math.hpp"
#include "core/ray.hpp"

namespace rise {

class Shape;

// The nearest intersection found so far along a ray. Intersection routines
// record only what they need to find the surface later (which shape, which
// triangle or face, barycentric coordinates); the normal and the point are
// computed once, by Shape::surfaceAt, for the nearest hit alone.
struct Hit {
  float t = kInfinity;
  const Shape* shape = nullptr;
  int primitive = 0;  // the triangle of a mesh, the face of a box, the part of a cylinder...
  Vec2 barycentric{0.0f};
};

// The surface at a hit: its point, its unit geometric normal, pointing out of
// the solid (or, for a triangle or polygon, to the side its vertices wind
// counter-clockwise around), and its texture coordinates.
struct SurfacePoint {
  Vec3 position;
  Vec3 normal;
  Vec2 uv{0.0f};
};

// What intersecting costs, counted per ray and summed into the render's
// statistics and its cost image.
struct IntersectionCounters {
  std::uint64_t tests = 0;  // ray-primitive tests: one per shape, one per triangle of a mesh
};

class Shape {
 public:
  explicit Shape(int material) : material_(material) {}
  virtual ~Shape() = default;

  // Finds the nearest intersection with t in (tMin, hit.t). On success it
  // records it in `hit` (t, shape, primitive data) and returns true; otherwise
  // leaves `hit` as it was.
  virtual bool intersect(const Ray& ray, float tMin, Hit& hit,
                         IntersectionCounters& counters) const = 0;

  // The point and normal of a hit that this shape recorded.
  virtual SurfacePoint surfaceAt(const Ray& ray, const Hit& hit) const = 0;

  // The box the shape stays inside (infinite for the plane).
  virtual Bounds3 bounds() const { return Bounds3::infinite(); }

  // A shape is made of primitives that an acceleration structure can bound
  // and test one at a time: a mesh of its triangles, any other shape of
  // itself alone.
  virtual int primitiveCount() const { return 1; }
  virtual Bounds3 primitiveBounds(int /*primitive*/) const { return bounds(); }
  virtual bool intersectPrimitive(int /*primitive*/, const Ray& ray, float tMin, Hit& hit,
                                  IntersectionCounters& counters) const {
    return intersect(ray, tMin, hit, counters);
  }

  // Index of the shape's material in Scene::materials.
  int material() const { return material_; }

 private:
  int material_;
};

}  // namespace rise
