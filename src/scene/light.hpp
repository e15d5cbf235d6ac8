#pragma once

#include "core/color.hpp"
#include "core/math.hpp"

namespace rise {

// What a light offers a surface point: the unit direction towards (a point
// of) the light, how far along it the light is (infinite for a directional
// light), and the light's colour there.
struct LightSample {
  Vec3 toLight;
  float distance;
  Color color;
};

// A light source. Lights do not fade with distance (as in Whitted's and the
// original RISE's model), and are not seen by camera rays: they light
// surfaces.
class Light {
 public:
  explicit Light(Color color) : color_(color) {}
  virtual ~Light() = default;

  // The light as seen from `point`, through the light's point chosen by the
  // sample u in the unit square. Lights of one point ignore u; area lights
  // spread their points over their area, so that averaging many samples gives
  // soft shadows (Cook, Porter & Carpenter 1984), and u = (1/2, 1/2) gives
  // their centre.
  virtual LightSample illuminate(const Vec3& point, const Vec2& u) const = 0;

  // The light as one point at its centre: hard shadows.
  LightSample illuminate(const Vec3& point) const { return illuminate(point, Vec2(0.5f)); }

  const Color& color() const { return color_; }

 protected:
  LightSample towards(const Vec3& point, const Vec3& lightPoint) const {
    const Vec3 offset = lightPoint - point;
    const float distance = glm::length(offset);
    return {offset / distance, distance, color_};
  }

 private:
  Color color_;
};

// Light from one point, equally in every direction.
class PointLight final : public Light {
 public:
  PointLight(Vec3 position, Color color) : Light(color), position_(position) {}

  LightSample illuminate(const Vec3& point, const Vec2&) const override {
    return towards(point, position_);
  }
  using Light::illuminate;

  const Vec3& position() const { return position_; }

 private:
  Vec3 position_;
};

// Parallel light from infinitely far away, like the sun; `direction` is the
// way the light travels.
class DirectionalLight final : public Light {
 public:
  DirectionalLight(Vec3 direction, Color color)
      : Light(color), direction_(normalizedOrZero(direction)) {}

  LightSample illuminate(const Vec3&, const Vec2&) const override {
    return {-direction_, kInfinity, color()};
  }
  using Light::illuminate;

  const Vec3& direction() const { return direction_; }

 private:
  Vec3 direction_;
};

// A parallelogram of light: corner + s edge1 + t edge2 for s, t in [0, 1].
class RectLight final : public Light {
 public:
  RectLight(Vec3 corner, Vec3 edge1, Vec3 edge2, Color color)
      : Light(color), corner_(corner), edge1_(edge1), edge2_(edge2) {}

  LightSample illuminate(const Vec3& point, const Vec2& u) const override {
    return towards(point, corner_ + u.x * edge1_ + u.y * edge2_);
  }
  using Light::illuminate;

 private:
  Vec3 corner_, edge1_, edge2_;
};

// A flat disk of light facing along `normal`.
class DiskLight final : public Light {
 public:
  DiskLight(Vec3 center, Vec3 normal, float radius, Color color);

  LightSample illuminate(const Vec3& point, const Vec2& u) const override;
  using Light::illuminate;

 private:
  Vec3 center_;
  Vec3 axisU_, axisV_;  // radius-long axes across the disk
};

// A ball of light. From afar it looks like a disk, its silhouette, so samples
// are spread over the disk through its centre facing the point: that disk
// casts the penumbra.
class SphereLight final : public Light {
 public:
  SphereLight(Vec3 center, float radius, Color color)
      : Light(color), center_(center), radius_(radius) {}

  LightSample illuminate(const Vec3& point, const Vec2& u) const override;
  using Light::illuminate;

 private:
  Vec3 center_;
  float radius_;
};

}  // namespace rise
