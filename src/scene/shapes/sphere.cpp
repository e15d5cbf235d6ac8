#include "scene/shapes/sphere.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "scene/textures/surface_mapping.hpp"

namespace rise {

namespace {

// The sphere's texture coordinates are its longitude and latitude around y.
const Vec3 kPolarAxis(0.0f, 1.0f, 0.0f);

}  // namespace

Sphere::Sphere(Vec3 center, float radius, int material)
    : Shape(material), center_(center), radius_(radius), radiusSquared_(radius * radius) {}

bool Sphere::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  if (!intersectSphere(ray, center_, radiusSquared_, tMin, hit.t, hit.t)) return false;
  hit.shape = this;
  return true;
}

bool Sphere::primitiveSphere(int /*primitive*/, Vec3& center, float& radiusSquared) const {
  center = center_;
  radiusSquared = radiusSquared_;
  return true;
}

SurfacePoint Sphere::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfacePoint surface = pointAt(ray, hit);
  surface.uv = sphericalUv(kPolarAxis, surface.normal);
  sphericalTangents(kPolarAxis, surface.position - center_, surface.dpdu, surface.dpdv);
  return surface;
}

SurfacePoint Sphere::pointAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  return {position, (position - center_) / radius_};
}

Bounds3 Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

// Rings of latitude around the y axis, pole to pole, joined by quads (planar
// trapezoids) and, at the poles, by triangles. Each ring repeats its first
// vertex at the end, with u = 1 instead of 0, and each pole has a vertex per
// segment, at the segment's middle u, so that the texture coordinates have
// no jump across the seam or at the poles.
void Sphere::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  const int segments = segmentsPerTurn(settings.level);
  const int rings = segments / 2;
  const std::vector<Vec3> around = directionsAround(kPolarAxis, segments);
  std::vector<int> above;
  for (int ring = 0; ring <= rings; ++ring) {
    const float v = 1.0f - static_cast<float>(ring) / static_cast<float>(rings);
    const bool atPole = ring == 0 || ring == rings;
    const float polar = kPi * static_cast<float>(ring) / static_cast<float>(rings);
    std::vector<int> ringVertices;
    for (int k = 0; k <= segments; ++k) {
      if (atPole && k == segments) break;
      const Vec3 normal =
          atPole ? (ring == 0 ? kPolarAxis : -kPolarAxis)
                 : std::sin(polar) * around[k % segments] + std::cos(polar) * kPolarAxis;
      const float step = atPole ? static_cast<float>(k) + 0.5f : static_cast<float>(k);
      ringVertices.push_back(
          out.addVertex({center_ + radius_ * normal, normal, {turnAtStep(step, segments), v}}));
    }
    for (int k = 0; ring > 0 && k < segments; ++k) {
      if (ring == 1)
        out.addTriangle(ringVertices[k], ringVertices[k + 1], above[k]);
      else if (ring == rings)
        out.addTriangle(ringVertices[k], above[k + 1], above[k]);
      else
        out.addConvexPolygon(
            std::array{ringVertices[k], ringVertices[k + 1], above[k + 1], above[k]});
    }
    above = std::move(ringVertices);
  }
  out.enclosesSolid = true;
}

// Rings of quadrilaterals from pole to pole, triangles at the poles.
std::uint64_t Sphere::tessellatedTriangles(int level) const {
  const auto segments = static_cast<std::uint64_t>(segmentsPerTurn(level));
  return segments * segments;
}

}  // namespace rise
