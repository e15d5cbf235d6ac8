#include "scene/shapes/convex_polygon.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "scene/shapes/plane.hpp"
#include "scene/textures/surface_mapping.hpp"

namespace rise {

namespace {

// How far from exact (relative to the polygon's size) planarity and convexity
// may be, for vertices that went through rounding.
constexpr float kRelativeTolerance = 1e-5f;

const Vec3& nextVertex(const std::vector<Vec3>& vertices, std::size_t i) {
  return vertices[nextCorner(i, vertices.size())];
}

// Twice the polygon's vector area, summed over its fan of triangles from the
// first vertex, which equals Newell's method (Tampieri, "Newell's Method for
// Computing the Plane Equation of a Polygon", Graphics Gems III, 1992). It
// points along the counter-clockwise normal and, unlike the cross product at
// one vertex, does not depend on which vertex is chosen or fail at a
// collinear one.
Vec3 doubleAreaVector(const std::vector<Vec3>& vertices) {
  Vec3 sum(0.0f);
  for (std::size_t i = 1; i + 1 < vertices.size(); ++i)
    sum += glm::cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]);
  return sum;
}

float largestDistanceFromFirst(const std::vector<Vec3>& vertices) {
  float largest = 0.0f;
  for (const Vec3& v : vertices) largest = std::max(largest, glm::length(v - vertices[0]));
  return largest;
}

}  // namespace

bool isPlanarConvexPolygon(const std::vector<Vec3>& vertices) {
  if (vertices.size() < 3) return false;
  for (const Vec3& v : vertices)
    if (!isFinite(v)) return false;

  const float size = largestDistanceFromFirst(vertices);
  const float tolerance = kRelativeTolerance * size;
  const Vec3 area = doubleAreaVector(vertices);
  const float areaLength = glm::length(area);
  if (!(areaLength > tolerance * size)) return false;  // collinear, or all one point
  const Vec3 normal = area / areaLength;

  for (const Vec3& v : vertices)
    if (std::abs(glm::dot(normal, v - vertices[0])) > tolerance) return false;

  // Convex and simple: every vertex is on the inner side of every edge (a star
  // polygon, whose turns all go the same way, fails this).
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 edge = nextVertex(vertices, i) - vertices[i];
    const Vec3 inward = glm::cross(normal, edge);
    const float allowedOutside = -tolerance * glm::length(edge);
    for (const Vec3& v : vertices)
      if (glm::dot(inward, v - vertices[i]) < allowedOutside) return false;
  }
  return true;
}

ConvexPolygon::ConvexPolygon(std::vector<Vec3> vertices, int material)
    : Shape(material),
      vertices_(std::move(vertices)),
      normal_(glm::normalize(doubleAreaVector(vertices_))) {
  assert(isPlanarConvexPolygon(vertices_));
  edgeInwardNormals_.reserve(vertices_.size());
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    edgeInwardNormals_.push_back(glm::cross(normal_, nextVertex(vertices_, i) - vertices_[i]));
  // The first edge that has a length: a polygon may repeat a vertex.
  std::size_t edge = 0;
  while (nextVertex(vertices_, edge) == vertices_[edge]) ++edge;
  uAxis_ = glm::normalize(nextVertex(vertices_, edge) - vertices_[edge]);
  vAxis_ = glm::cross(normal_, uAxis_);
  Vec2 lowest(kInfinity), highest(-kInfinity);
  for (const Vec3& vertex : vertices_) {
    const Vec2 mapped = planarUv(vertex, vertices_[0], uAxis_, vAxis_);
    lowest = glm::min(lowest, mapped);
    highest = glm::max(highest, mapped);
  }
  uvLowest_ = lowest;
  uvSize_ = highest - lowest;
}

Vec2 ConvexPolygon::textureCoordinates(const Vec3& position) const {
  return (planarUv(position, vertices_[0], uAxis_, vAxis_) - uvLowest_) / uvSize_;
}

bool ConvexPolygon::intersect(const Ray& ray, float tMin, Hit& hit,
                              IntersectionCounters& counters) const {
  ++counters.tests;
  float t;
  if (!intersectPlane(ray, vertices_[0], normal_, tMin, hit.t, t)) return false;
  const Vec3 point = ray.at(t);
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    if (glm::dot(edgeInwardNormals_[i], point - vertices_[i]) < 0.0f) return false;
  hit.t = t;
  hit.shape = this;
  return true;
}

SurfacePoint ConvexPolygon::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  SurfacePoint surface(position, normal_, textureCoordinates(position));
  surface.dpdu = uvSize_.x * uAxis_;
  surface.dpdv = uvSize_.y * vAxis_;
  return surface;
}

Bounds3 ConvexPolygon::bounds() const {
  Bounds3 box;
  for (const Vec3& vertex : vertices_) box.grow(vertex);
  return box;
}

void ConvexPolygon::tessellate(const TessellationSettings&, Tessellation& out) const {
  std::vector<int> corners;
  for (const Vec3& vertex : vertices_)
    corners.push_back(out.addVertex({vertex, normal_, textureCoordinates(vertex)}));
  out.addConvexPolygon(corners);
}

}  // namespace rise
