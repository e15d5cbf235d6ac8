#include "shading/material_at_point.hpp"

#include "shading/bump_mapping.hpp"

namespace rise {

SurfaceColors surfaceColors(const Material& material, const SurfacePoint& surface) {
  return {
      material.texture ? material.texture->colorAt(surface) : material.color,
      material.ksTexture ? material.ks * material.ksTexture->colorAt(surface) : Color(material.ks)};
}

SurfaceColors surfaceColors(const Material& material, const SurfacePoint& surface,
                            const PixelFootprint& footprint) {
  return {
      material.texture ? material.texture->colorOverFootprint(surface, footprint) : material.color,
      material.ksTexture ? material.ks * material.ksTexture->colorOverFootprint(surface, footprint)
                         : Color(material.ks)};
}

Vec3 shadingNormal(const Material& material, const SurfacePoint& surface) {
  // The point is copied only where a normal map tilts it before a bump map.
  if (!material.normalMap)
    return material.bump ? bumped(*material.bump, surface) : surface.shadingNormal;
  SurfacePoint tilted = surface;
  tilted.shadingNormal = normalMapped(*material.normalMap, surface);
  return material.bump ? bumped(*material.bump, tilted) : tilted.shadingNormal;
}

}  // namespace rise
