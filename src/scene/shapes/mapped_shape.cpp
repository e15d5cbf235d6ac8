#include "scene/shapes/mapped_shape.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rise {

namespace {

// The most pieces a triangle's side is cut into.
constexpr int kMostPieces = 64;

// Into how many pieces each side of every triangle is cut so that none is
// longer than `longestPiece`.
int piecesPerSide(const Tessellation& surface, float longestPiece) {
  float longest = 0.0f;
  for (const auto& triangle : surface.triangles)
    for (int corner = 0; corner < 3; ++corner)
      longest =
          std::max(longest, glm::length(surface.vertices[triangle[corner]].position -
                                        surface.vertices[triangle[(corner + 1) % 3]].position));
  return std::clamp(static_cast<int>(std::ceil(longest / longestPiece)), 1, kMostPieces);
}

// The point of the triangle with whole-number weights (a, b, c) summing to
// `pieces`. Terms of zero weight add exactly nothing, and sums do not depend
// on their order, so that two triangles find the same points on the side
// they share, to the bit.
SurfaceVertex pointOf(const std::array<SurfaceVertex, 3>& corners,
                      const std::array<int, 3>& weights, int pieces) {
  Vec3 position(0.0f), normal(0.0f);
  for (int corner = 0; corner < 3; ++corner) {
    position += static_cast<float>(weights[corner]) * corners[corner].position;
    normal += static_cast<float>(weights[corner]) * corners[corner].normal;
  }
  return {position / static_cast<float>(pieces), glm::normalize(normal)};
}

}  // namespace

MappedShape::MappedShape(std::unique_ptr<Shape> shape, const Mapping& mapping)
    : Shape(shape->material()), shape_(std::move(shape)), mapping_(mapping, shape_->bounds()) {}

bool MappedShape::intersect(const Ray& ray, float tMin, Hit& hit,
                            IntersectionCounters& counters) const {
  if (!shape_->intersect(ray, tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

SurfacePoint MappedShape::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfacePoint surface = shape_->surfaceAt(ray, hit);
  surface.uv = mapping_.uvAt(surface.position, surface.normal);
  mapping_.tangentsAt(surface.position, surface.normal, surface.dpdu, surface.dpdv);
  return surface;
}

Bounds3 MappedShape::bounds() const { return shape_->bounds(); }

int MappedShape::primitiveCount() const { return shape_->primitiveCount(); }

Bounds3 MappedShape::primitiveBounds(int primitive) const {
  return shape_->primitiveBounds(primitive);
}

bool MappedShape::intersectPrimitive(int primitive, const Ray& ray, float tMin, Hit& hit,
                                     IntersectionCounters& counters) const {
  if (!shape_->intersectPrimitive(primitive, ray, tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

bool MappedShape::primitiveTriangle(int primitive, std::array<Vec3, 3>& corners) const {
  return shape_->primitiveTriangle(primitive, corners);
}

void MappedShape::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  Tessellation surface;
  shape_->tessellate(settings, surface);
  const float segment = kPi * glm::length(mapping_.bounds().extent()) /
                        static_cast<float>(segmentsPerTurn(settings.level));
  const int pieces = mapping_.turns() ? piecesPerSide(surface, segment) : 1;
  // Vertices that triangles share when they give them the same coordinates.
  std::map<std::array<float, 8>, int> shared;
  const auto vertexFor = [&](const SurfaceVertex& vertex) {
    const Vec3& p = vertex.position;
    const Vec3& n = vertex.normal;
    const auto [found, isNew] =
        shared.try_emplace({p.x, p.y, p.z, n.x, n.y, n.z, vertex.uv.x, vertex.uv.y},
                           static_cast<int>(out.vertices.size()));
    if (isNew) out.addVertex(vertex);
    return found->second;
  };
  const auto addPiece = [&](const std::array<SurfaceVertex, 3>& corners,
                            const std::array<std::array<int, 3>, 3>& weights, int primitive) {
    std::array<SurfaceVertex, 3> piece;
    for (int corner = 0; corner < 3; ++corner)
      piece[corner] = pointOf(corners, weights[corner], pieces);
    const std::array<Vec2, 3> uvs =
        mapping_.cornerUvs({piece[0].position, piece[1].position, piece[2].position});
    for (int corner = 0; corner < 3; ++corner) piece[corner].uv = uvs[corner];
    out.addTriangle(vertexFor(piece[0]), vertexFor(piece[1]), vertexFor(piece[2]), primitive);
  };
  for (std::size_t triangle = 0; triangle < surface.triangles.size(); ++triangle) {
    const auto& [a, b, c] = surface.triangles[triangle];
    const int primitive = surface.primitives[triangle];
    const std::array corners{surface.vertices[a], surface.vertices[b], surface.vertices[c]};
    // The grid of points i steps towards b and j towards c: a piece pointing
    // as the triangle does at each, and one pointing back between them.
    for (int i = 0; i < pieces; ++i) {
      for (int j = 0; i + j < pieces; ++j) {
        const int rest = pieces - i - j;
        addPiece(corners, {{{rest, i, j}, {rest - 1, i + 1, j}, {rest - 1, i, j + 1}}}, primitive);
        if (rest >= 2)
          addPiece(corners,
                   {{{rest - 1, i + 1, j}, {rest - 2, i + 1, j + 1}, {rest - 1, i, j + 1}}},
                   primitive);
      }
    }
  }
  out.enclosesSolid = surface.enclosesSolid;
}

}  // namespace rise
