// A bump map: a height over the surface, read from a texture (Blinn 1978;
// shading/bump_mapping.hpp uses it).
#pragma once

#include <memory>

#include "scene/textures/texture.hpp"

namespace rise {

class BumpMap {
 public:
  // The height is the mean of the texture's red, green and blue, times
  // `strength` (in the units of the scene); `step` is the texture-coordinate
  // distance over which its slope is measured (one texel for an image).
  BumpMap(std::shared_ptr<const Texture> height, float strength, Vec2 step)
      : height_(std::move(height)), strength_(strength), step_(step) {}

  // The height at the point of the surface where the coordinates are `uv`.
  float heightAt(const SurfacePoint& surface, const Vec2& uv) const;
  const Vec2& step() const { return step_; }

 private:
  std::shared_ptr<const Texture> height_;
  float strength_;
  Vec2 step_;
};

}  // namespace rise
