// Solid textures from Perlin's noise (scene/perlin_noise.hpp): a colour
// between two, chosen at each point of space, so that a surface looks carved
// from the material whatever its shape ("An Image Synthesizer", Perlin,
// SIGGRAPH 1985). The point is the surface's position in the world, times
// `scale` (larger is finer).
#pragma once

#include "scene/textures/texture.hpp"

namespace rise {

enum class NoisePattern {
  Perlin,  // the noise itself: soft blotches about one unit across
  Marble,  // veins: a sine across x, its phase disturbed by turbulence
  Wood,    // rings around the y axis, made slightly irregular by the noise
};

class NoiseTexture final : public Texture {
 public:
  NoiseTexture(NoisePattern pattern, Color first, Color second, float scale)
      : pattern_(pattern), first_(first), second_(second), scale_(scale) {}

  Color colorAt(const SurfacePoint& surface) const override;

  // How far from the first colour towards the second the point is, in [0, 1].
  float mixAt(const Vec3& position) const;

 private:
  NoisePattern pattern_;
  Color first_;
  Color second_;
  float scale_;
};

}  // namespace rise
