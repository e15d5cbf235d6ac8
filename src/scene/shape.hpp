#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/bounds.hpp"
#include "core/math.hpp"
#include "core/ray.hpp"
#include "scene/tessellation.hpp"

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
// counter-clockwise around), its texture coordinates, and the unit normal that
// shading uses. The shading normal is the geometric one, except on a mesh with
// vertex normals, where it is interpolated across each triangle so that the
// facets do not show (Phong, "Illumination for Computer Generated Pictures",
// CACM 18(6), 1975); it is always on the same side as `normal`. dpdu and dpdv
// are how the position changes with the texture coordinates, the tangents
// along which a bump map tilts the shading normal; zero where a surface has
// no such mapping.
// The flat triangle a point lies on and the normals its corners carry,
// where the shading normal is interpolated between them (a smooth mesh): the
// smooth surface those normals describe lies above the flat one, and a
// shadow ray may leave from it (ray/shadow_terminator.hpp).
struct NormalInterpolation {
  std::array<Vec3, 3> corners;
  std::array<Vec3, 3> normals;
  Vec3 weights;  // the point's barycentric coordinates, corner by corner
};

struct SurfacePoint {
  SurfacePoint() = default;
  SurfacePoint(const Vec3& position, const Vec3& normal, const Vec2& uv = Vec2(0.0f))
      : position(position), normal(normal), uv(uv), shadingNormal(normal) {}

  Vec3 position{0.0f};
  Vec3 normal{0.0f};
  Vec2 uv{0.0f};
  Vec3 shadingNormal{0.0f};
  Vec3 dpdu{0.0f};
  Vec3 dpdv{0.0f};
  std::optional<NormalInterpolation> interpolation;
};

// What intersecting costs, counted per ray and summed into the render's
// statistics and its cost image.
struct IntersectionCounters {
  std::uint64_t tests = 0;         // ray-primitive tests: one per shape, one per triangle of a mesh
  std::uint64_t nodesVisited = 0;  // bounding volumes tested: BVH boxes, bounding spheres

  IntersectionCounters& operator+=(const IntersectionCounters& other) {
    tests += other.tests;
    nodesVisited += other.nodesVisited;
    return *this;
  }
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
  // The same without the texture coordinates and tangents (left zero), for
  // a material that reads neither (Material::readsTextureFrame). A shape
  // whose coordinates cost more than its point (a sphere's arc functions)
  // finds the point alone; the others give surfaceAt's answer.
  virtual SurfacePoint pointAt(const Ray& ray, const Hit& hit) const { return surfaceAt(ray, hit); }

  // The box the shape stays inside (infinite for the plane).
  virtual Bounds3 bounds() const = 0;

  // A shape is made of primitives that an acceleration structure can bound
  // and test one at a time: a mesh of its triangles, any other shape of
  // itself alone.
  virtual int primitiveCount() const { return 1; }
  virtual Bounds3 primitiveBounds(int /*primitive*/) const { return bounds(); }
  virtual bool intersectPrimitive(int /*primitive*/, const Ray& ray, float tMin, Hit& hit,
                                  IntersectionCounters& counters) const {
    return intersect(ray, tMin, hit, counters);
  }
  // The world-space corners of a primitive that is a triangle standing
  // still and that intersectPrimitive tests as intersectTriangle
  // (shapes/triangle.hpp) on these very corners, recording t, the
  // barycentric coordinates, the shape and the primitive. An acceleration
  // structure may then test it itself, without a call into the shape (the
  // BVH in its leaves, Embree as its own triangles), and find the same hit
  // to the bit. False for any other primitive.
  virtual bool primitiveTriangle(int /*primitive*/, std::array<Vec3, 3>& /*corners*/) const {
    return false;
  }
  // The same for a primitive that is a sphere standing still, tested as
  // intersectSphere (shapes/sphere.hpp) on this centre and squared radius,
  // recording t and the shape.
  virtual bool primitiveSphere(int /*primitive*/, Vec3& /*center*/,
                               float& /*radiusSquared*/) const {
    return false;
  }

  // Fills `out` (empty) with triangles covering the surface, for the
  // algorithms that draw polygons (raster/): finer as settings.level grows,
  // every vertex on the exact surface with its normal and texture
  // coordinates.
  virtual void tessellate(const TessellationSettings& settings, Tessellation& out) const = 0;
  // The triangles tessellate() makes at `level`, at most, known without
  // making them: the visible-surface algorithms' memory is worked out from
  // them before a render (Renderer::needs). A shape of a few flat faces
  // makes about as many as its primitives.
  virtual std::uint64_t tessellatedTriangles(int /*level*/) const {
    return static_cast<std::uint64_t>(primitiveCount());
  }

  // Whether tessellate()'s triangles are the surface itself at any level, as
  // a polygon's, a box's and a still mesh's are: points chosen on them are
  // points of the surface (the path tracer's lights, ray/emitters.hpp).
  virtual bool tessellationIsExact() const { return false; }

  // Index of the shape's material in Scene::materials.
  int material() const { return material_; }

 private:
  int material_;
};

}  // namespace rise
