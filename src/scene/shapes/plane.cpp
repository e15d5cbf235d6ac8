#include "scene/shapes/plane.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace rise {

bool intersectPlane(const Ray& ray, Vec3 point, Vec3 normal, float tMin, float tMax, float& t) {
  const float approach = glm::dot(normal, ray.direction);
  if (approach == 0.0f) return false;
  const float tPlane = glm::dot(normal, point - ray.origin) / approach;
  if (!(tPlane > tMin && tPlane < tMax)) return false;
  t = tPlane;
  return true;
}

namespace {

Vec3 textureUAxis(const Vec3& normal) {
  const Vec3 reference =
      std::abs(normal.x) > 0.9f ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(reference - glm::dot(reference, normal) * normal);
}

}  // namespace

Plane::Plane(Vec3 point, Vec3 normal, int material)
    : Shape(material),
      point_(point),
      normal_(glm::normalize(normal)),
      uAxis_(textureUAxis(normal_)),
      vAxis_(glm::cross(normal_, uAxis_)) {}

bool Plane::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  if (!intersectPlane(ray, point_, normal_, tMin, hit.t, hit.t)) return false;
  hit.shape = this;
  return true;
}

SurfacePoint Plane::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  SurfacePoint surface(position, normal_, textureCoordinates(position));
  surface.dpdu = uAxis_;
  surface.dpdv = vAxis_;
  return surface;
}

Vec2 Plane::textureCoordinates(const Vec3& position) const {
  const Vec3 offset = position - point_;
  return {glm::dot(offset, uAxis_), glm::dot(offset, vAxis_)};
}

Bounds3 Plane::bounds() const { return Bounds3::infinite(); }

// A square grid centred at the foot of the perpendicular from the viewpoint.
// Its lines are spaced as the cube of their distance from the centre, so that
// the cells near the camera, which look large, are small, and the far ones,
// which look small, are large.
void Plane::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  const Vec3 foot = settings.viewpoint - glm::dot(settings.viewpoint - point_, normal_) * normal_;
  const int steps = settings.level;
  std::vector<float> lines;
  for (int i = -steps; i <= steps; ++i) {
    const float fraction = static_cast<float>(i) / static_cast<float>(steps);
    lines.push_back(0.5f * settings.planeSize * fraction * fraction * fraction);
  }
  const int count = static_cast<int>(lines.size());
  for (float v : lines) {
    for (float u : lines) {
      const Vec3 position = foot + u * uAxis_ + v * vAxis_;
      out.addVertex({position, normal_, textureCoordinates(position)});
    }
  }
  // u x v is the normal: u then v turns counter-clockwise around it.
  for (int row = 0; row + 1 < count; ++row) {
    for (int column = 0; column + 1 < count; ++column) {
      const int corner = row * count + column;
      out.addConvexPolygon(std::array{corner, corner + 1, corner + count + 1, corner + count});
    }
  }
}

// A square of 2 level x 2 level quadrilaterals.
std::uint64_t Plane::tessellatedTriangles(int level) const {
  return 8 * static_cast<std::uint64_t>(level) * static_cast<std::uint64_t>(level);
}

}  // namespace rise
