// Shapes as triangles, for the algorithms that draw polygons instead of
// tracing rays (raster/). Every vertex lies on the exact surface and carries
// the surface's normal and texture coordinates there, so that interpolating
// them across a triangle approximates the surface the ray tracer sees: the
// finer the tessellation, the closer.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/math.hpp"

namespace rise {

class ProjectedMapping;
class Shape;

// How finely curved surfaces are cut by default: a circle into 32 segments.
inline constexpr int kDefaultTessellationLevel = 8;
// The default side of the square that stands in for an infinite plane. Seen
// from a height h, the square ends short of the plane's horizon by the angle
// atan(2 h / side); this side keeps that angle under a tenth of a pixel for
// eyes a few units up, so that the floor reaches the horizon as the ray
// tracer's does. Depths and texture coordinates stay well within a float's
// precision.
inline constexpr float kDefaultPlaneSize = 100000.0f;

struct TessellationSettings {
  // How finely curved surfaces are cut: a circle becomes 4 * level segments,
  // a sphere's meridian 2 * level.
  int level = kDefaultTessellationLevel;
  // The side of the square that stands in for an infinite plane, centred at
  // the foot of the perpendicular from `viewpoint`, under the camera.
  float planeSize = kDefaultPlaneSize;
  Vec3 viewpoint{0.0f};
  // The instant drawn: moving shapes are tessellated where they are then.
  float time = 0.0f;
};

// A point of a surface, as a corner of the triangles that cover it.
struct SurfaceVertex {
  Vec3 position;
  // The exact surface's unit normal there, or a flat face's; but where the
  // surface's normals converge to a point that has none of its own (a
  // cone's apex), shorter, down to zero at the point: interpolation across
  // a triangle weighs each corner's normal, and its colour in Gouraud
  // shading, by its length, so that the other corners decide near that
  // point.
  Vec3 normal;
  Vec2 uv{0.0f};
};

// The triangles that cover one shape. Each winds counter-clockwise seen from
// the side its vertices' normals face (outside, for a solid).
struct Tessellation {
  std::vector<SurfaceVertex> vertices;
  std::vector<std::array<int, 3>> triangles;
  // For each triangle, the primitive of the shape it lies on (the argument of
  // Shape::intersectPrimitive): a mesh's own triangle, 0 for a shape that is
  // one primitive. A ray through a triangle's pixels may then be tested
  // against the exact surface under it alone.
  std::vector<int> primitives;
  // The triangles close around a solid: seen from outside it, a triangle
  // facing away from the eye is always hidden behind one facing it, so it can
  // be culled. Open surfaces (planes, polygons, most meshes) are seen from
  // both sides.
  bool enclosesSolid = false;
  // The projected mapping the shape wears (shapes/mapped_shape.hpp), or
  // none. A projection is not affine across a triangle: a renderer computes
  // the texture coordinates at each point by it, as the ray tracer does at
  // each hit, rather than interpolating the corners'. `projectionPlacement`
  // takes the space the projection is made in to the triangles'.
  const ProjectedMapping* projection = nullptr;
  Mat4 projectionPlacement{1.0f};

  int addVertex(const SurfaceVertex& vertex) {
    vertices.push_back(vertex);
    return static_cast<int>(vertices.size()) - 1;
  }
  // A triangle on the shape's `primitive`; one with a repeated corner (a
  // sphere's pole) is left out.
  void addTriangle(int a, int b, int c, int primitive = 0) {
    if (a == b || b == c || c == a) return;
    triangles.push_back({a, b, c});
    primitives.push_back(primitive);
  }
  // A planar convex polygon, as the fan of triangles from its first corner.
  void addConvexPolygon(std::span<const int> corners);
};

// Tessellates `shape`, defined in its own space, and places the result in the
// world by an affine map: positions by the map, normals by its inverse
// transpose, and the winding reversed when the map mirrors, so that it still
// turns counter-clockwise around the normals.
void tessellatePlaced(const Shape& shape, const Mat4& worldFromObject,
                      const TessellationSettings& settings, Tessellation& out);

// Whether the triangles close around a solid: welded where their corners
// coincide, every edge is shared by exactly two triangles that run along it
// in opposite directions (a closed, consistently wound surface).
bool enclosesSolid(std::span<const Vec3> positions, std::span<const std::array<int, 3>> triangles);

// The number of segments that approximate a full circle at this level.
int segmentsPerTurn(int level);

// The unit directions across a unit axis at `segments` equal angles around
// it, turning counter-clockwise seen from the axis's tip; the same for the
// same axis, so that rings around one axis line up.
std::vector<Vec3> directionsAround(const Vec3& axis, int segments);

}  // namespace rise
