#include "ray/emitters.hpp"

#include <algorithm>

#include "core/warps.hpp"

namespace rise {

Emitters::Emitters(const Scene& scene) {
  for (const auto& shape : scene.shapes) {
    const Material& material = scene.materialOf(*shape);
    if (material.emits() && luminance(material.emission) > 0.0f)
      addShape(*shape, material.emission);
  }
  float power = 0.0f;
  for (const Part& part : parts_) {
    power += luminance(part.radiance) * part.area;
    cumulativePower_.push_back(power);
  }
}

void Emitters::addShape(const Shape& shape, const Color& radiance) {
  Vec3 center;
  float radiusSquared = 0.0f;
  if (shape.primitiveCount() == 1 && shape.primitiveSphere(0, center, radiusSquared)) {
    const float radius = std::sqrt(radiusSquared);
    parts_.push_back({{center, center, center}, radius, 4.0f * kPi * radiusSquared, radiance});
    sampled_.insert(&shape);
    return;
  }
  if (!shape.tessellationIsExact()) return;
  Tessellation tessellation;
  shape.tessellate({}, tessellation);
  for (const std::array<int, 3>& triangle : tessellation.triangles) {
    Part part;
    for (int corner = 0; corner < 3; ++corner)
      part.corners[corner] =
          tessellation.vertices[static_cast<std::size_t>(triangle[corner])].position;
    part.area = 0.5f * glm::length(glm::cross(part.corners[1] - part.corners[0],
                                              part.corners[2] - part.corners[0]));
    part.radiance = radiance;
    if (part.area > 0.0f) parts_.push_back(part);
  }
  sampled_.insert(&shape);
}

EmitterPoint Emitters::sample(float choice, const Vec2& u) const {
  const float total = cumulativePower_.back();
  const auto chosen =
      std::upper_bound(cumulativePower_.begin(), cumulativePower_.end(), choice * total);
  const Part& part = parts_[static_cast<std::size_t>(
      std::min<std::ptrdiff_t>(chosen - cumulativePower_.begin(), count() - 1))];
  EmitterPoint point;
  point.radiance = part.radiance;
  point.areaDensity = luminance(part.radiance) / total;
  if (part.radius > 0.0f) {
    point.normal = squareToUniformSphere(u);
    point.position = part.corners[0] + part.radius * point.normal;
    return point;
  }
  // Uniform over the triangle: the square folded onto it.
  const Vec2 folded = u.x + u.y > 1.0f ? Vec2(1.0f - u.x, 1.0f - u.y) : u;
  const Vec3 edge1 = part.corners[1] - part.corners[0], edge2 = part.corners[2] - part.corners[0];
  point.position = part.corners[0] + folded.x * edge1 + folded.y * edge2;
  point.normal = glm::normalize(glm::cross(edge1, edge2));
  return point;
}

float Emitters::areaDensity(const Shape& shape, const Color& radiance) const {
  if (empty() || !sampled_.contains(&shape)) return 0.0f;
  return luminance(radiance) / cumulativePower_.back();
}

}  // namespace rise
