// Shadows as the one shading model sees them: a question it asks for each
// light at each point it shades, whoever answers it. With no answerer every
// light reaches every surface facing it; the visible-surface algorithms
// answer with shadow maps (raster/shadow_map.hpp), so that flat, Gouraud and
// Phong shading, and every algorithm, take shadows the same way.
#pragma once

#include "core/color.hpp"
#include "core/math.hpp"

namespace rise {

class LightVisibility {
 public:
  virtual ~LightVisibility() = default;

  // How much of light number `light` (in Scene::lights) reaches `position`,
  // channel by channel: 1 where nothing stands in its way, 0 in full shadow,
  // between where a transparent surface filters it or the point lies on a
  // shadow's edge. `normal` is the surface's own normal there, on the side
  // the light is.
  virtual Color reaching(int light, const Vec3& position, const Vec3& normal) const = 0;
};

}  // namespace rise
