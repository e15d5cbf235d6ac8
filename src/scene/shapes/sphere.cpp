#include "scene/shapes/sphere.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "scene/shapes/quadratic.hpp"

namespace rise {

Sphere::Sphere(Vec3 center, float radius, int material)
    : Shape(material), center_(center), radius_(radius), radiusSquared_(radius * radius) {}

bool Sphere::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  const Vec3 fromCenter = ray.origin - center_;
  // Most rays start outside a sphere and go away from it, or miss it wide:
  // tell them apart before solving anything.
  const float halfB = glm::dot(fromCenter, ray.direction);
  if (halfB > 0.0f && glm::dot(fromCenter, fromCenter) > radiusSquared_) return false;
  float roots[2];
  if (!solveLineAtDistance(fromCenter, ray.direction, radiusSquared_, roots[0], roots[1]))
    return false;
  for (float t : roots) {
    if (t > tMin && t < hit.t) {
      hit.t = t;
      hit.shape = this;
      return true;
    }
  }
  return false;
}

SurfacePoint Sphere::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  return {position, (position - center_) / radius_};
}

Bounds3 Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

// Rings of latitude around the y axis, pole to pole, joined by quads (planar
// trapezoids) and, at the poles, by triangles.
void Sphere::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  const Vec3 axis(0.0f, 1.0f, 0.0f);
  const int segments = segmentsPerTurn(settings.level);
  const int rings = segments / 2;
  const std::vector<Vec3> around = directionsAround(axis, segments);
  const auto vertexAt = [&](const Vec3& normal) {
    return out.addVertex({center_ + radius_ * normal, normal});
  };
  std::vector<int> upper(segments, vertexAt(axis));
  for (int ring = 1; ring <= rings; ++ring) {
    std::vector<int> lower;
    if (ring == rings) {
      lower.assign(segments, vertexAt(-axis));
    } else {
      const float polar = kPi * static_cast<float>(ring) / static_cast<float>(rings);
      for (const Vec3& direction : around)
        lower.push_back(vertexAt(std::sin(polar) * direction + std::cos(polar) * axis));
    }
    for (int k = 0; k < segments; ++k) {
      const int next = (k + 1) % segments;
      out.addConvexPolygon(std::array{lower[k], lower[next], upper[next], upper[k]});
    }
    upper = std::move(lower);
  }
  out.enclosesSolid = true;
}

}  // namespace rise
