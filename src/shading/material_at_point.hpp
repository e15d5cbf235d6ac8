// What a material shows at a point of its surface, the same for every
// algorithm: the two colours of the Phong model that may vary over it, C and
// ks, with its textures looked up there; and the normal that shading uses,
// tilted by its normal map and then its bump map (shading/bump_mapping.hpp).
#pragma once

#include "scene/material.hpp"
#include "scene/shape.hpp"

namespace rise {

// C and ks at a point, per channel.
struct SurfaceColors {
  Color color;  // C: the colour or the texture there
  Color ks;     // the specular coefficient times the ks texture there
};

SurfaceColors surfaceColors(const Material& material, const SurfacePoint& surface);

// The same averaged over a pixel's footprint in the texture, for the
// algorithms that know it (the visible-surface algorithms, for mipmaps).
SurfaceColors surfaceColors(const Material& material, const SurfacePoint& surface,
                            const PixelFootprint& footprint);

// The shading normal at the point: the surface's own, replaced by the normal
// map's where there is one, then tilted by the bump map's.
Vec3 shadingNormal(const Material& material, const SurfacePoint& surface);

}  // namespace rise
