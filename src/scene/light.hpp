#pragma once

#include "core/color.hpp"
#include "core/math.hpp"

namespace rise {

// What a light offers a surface point: the unit direction towards the light,
// how far along it the light is (infinite for a directional light), and the
// light's colour there.
struct LightSample {
  Vec3 toLight;
  float distance;
  Color color;
};

class Light {
 public:
  explicit Light(Color color) : color_(color) {}
  virtual ~Light() = default;

  virtual LightSample illuminate(const Vec3& point) const = 0;

  const Color& color() const { return color_; }

 private:
  Color color_;
};

// Light from one point, equally in every direction, with no fall-off over
// distance (as in Whitted's and the original RISE's model).
class PointLight final : public Light {
 public:
  PointLight(Vec3 position, Color color) : Light(color), position_(position) {}

  LightSample illuminate(const Vec3& point) const override {
    const Vec3 offset = position_ - point;
    const float distance = glm::length(offset);
    return {offset / distance, distance, color()};
  }

  const Vec3& position() const { return position_; }

 private:
  Vec3 position_;
};

// Parallel light from infinitely far away, like the sun; `direction` is the
// way the light travels.
class DirectionalLight final : public Light {
 public:
  DirectionalLight(Vec3 direction, Color color)
      : Light(color), direction_(glm::normalize(direction)) {}

  LightSample illuminate(const Vec3&) const override { return {-direction_, kInfinity, color()}; }

  const Vec3& direction() const { return direction_; }

 private:
  Vec3 direction_;
};

}  // namespace rise
