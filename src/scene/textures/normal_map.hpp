// Normal mapping: the shading normal read from an image in tangent space,
// its red, green and blue (linear, in [0, 1]) mapping to -1..1 along the
// directions in which u grows, in which v grows (both made perpendicular to
// the normal) and along the normal, so that the flat colour (0.5, 0.5, 1)
// leaves the normal as it is. As with a bump map (scene/bump_map.hpp), only
// shading sees the tilted normal.
#pragma once

#include <memory>

#include "scene/textures/texture.hpp"

namespace rise {

class NormalMap {
 public:
  explicit NormalMap(std::shared_ptr<const Texture> map) : map_(std::move(map)) {}

  // The shading normal at `surface`; a surface without tangents (dpdu = 0)
  // keeps its own.
  Vec3 shadingNormalAt(const SurfacePoint& surface) const;

 private:
  std::shared_ptr<const Texture> map_;
};

}  // namespace rise
