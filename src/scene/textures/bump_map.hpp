// Bump mapping (J. F. Blinn, "Simulation of Wrinkled Surfaces", SIGGRAPH
// 1978): the surface is imagined moved along its normal N by a height F(u, v)
// read from a texture, and shaded with the normal of that moved surface,
//
//   N' = N + Fu (N x Pv) + Fv (Pu x N)      (N of unit length here)
//
// where Pu and Pv are dP/du and dP/dv and Fu, Fv the height's derivatives,
// taken by central differences. N' is scaled by |Pu x Pv| so that the slope
// does not depend on how the texture is stretched. The surface itself does
// not move: intersections, silhouettes and shadows stay those of the smooth
// surface, only the shading normal tilts.
#pragma once

#include <memory>

#include "scene/textures/texture.hpp"

namespace rise {

class BumpMap {
 public:
  // The height is the mean of the texture's red, green and blue, times
  // `strength` (in the units of the scene); `step` is the texture-coordinate
  // distance of the differences (one texel for an image).
  BumpMap(std::shared_ptr<const Texture> height, float strength, Vec2 step)
      : height_(std::move(height)), strength_(strength), step_(step) {}

  // The shading normal of the bumped surface at `surface`, on the side of its
  // shading normal. A surface without tangents (Pu x Pv = 0) keeps its normal.
  Vec3 shadingNormalAt(const SurfacePoint& surface) const;

 private:
  float heightAt(const SurfacePoint& surface, const Vec2& uv) const;

  std::shared_ptr<const Texture> height_;
  float strength_;
  Vec2 step_;
};

}  // namespace rise
