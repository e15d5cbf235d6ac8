// The choices a path makes at the surfaces it meets, which Whitted's
// recursion (ray_tracing.cpp) leaves open: Whitted answers each with one
// ray, Cook (distributed_ray_tracing.cpp) with a sample.
#pragma once

#include "core/math.hpp"
#include "scene/light.hpp"

namespace rise {

// `depth` is the surface's place along the path (1: seen from the eye): where
// on a light a shadow ray aims, and where a reflected or refracted ray goes,
// given the ideal direction, the material's roughness and the surface's
// normal on the side the ray left from.
class PathChoices {
 public:
  virtual LightSample aimAt(const Light& light, const Vec3& point, int depth) = 0;
  virtual Vec3 scatter(const Vec3& ideal, float roughness, const Vec3& normal, int depth) = 0;

 protected:
  ~PathChoices() = default;
};

// Whitted's one ray for every choice: the light's centre, the ideal
// direction.
class SingleRayChoices final : public PathChoices {
 public:
  LightSample aimAt(const Light& light, const Vec3& point, int) override {
    return light.illuminate(point);
  }
  Vec3 scatter(const Vec3& ideal, float, const Vec3&, int) override { return ideal; }
};

}  // namespace rise
