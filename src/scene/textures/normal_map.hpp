// A normal map: the shading normal in tangent space, read from an image
// (shading/bump_mapping.hpp uses it).
#pragma once

#include <memory>

#include "scene/textures/texture.hpp"

namespace rise {

class NormalMap {
 public:
  explicit NormalMap(std::shared_ptr<const Texture> map) : map_(std::move(map)) {}

  // The map's colour at the point: red, green and blue in [0, 1].
  Color colorAt(const SurfacePoint& surface) const { return map_->colorAt(surface); }

 private:
  std::shared_ptr<const Texture> map_;
};

}  // namespace rise
