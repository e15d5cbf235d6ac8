// Shadow maps, after Williams (1978), filtered as Reeves, Salesin and Cook
// (1987) filter them; the idea and the bias are told in shadow_map.cpp.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "core/image.hpp"
#include "core/parallel.hpp"
#include "core/stats.hpp"
#include "raster/axis_view.hpp"
#include "raster/tessellated_scene.hpp"
#include "shading/light_visibility.hpp"

namespace rise {

struct ShadowMapSettings {
  int size = 1024;       // texels a side of each map
  float bias = 1.5f;     // how far, in texels, a point must lie behind a map's depth to be shadowed
  int filterRadius = 1;  // percentage-closer filtering over (2 r + 1)^2 texels; 0: one texel
};

// One depth image: for each texel, the depth of the nearest opaque surface,
// and, when the scene has transparent ones, the depth and material of the
// nearest transparent surface in front of it (infinite depth: none).
struct DepthMap {
  AxisView view;  // a face of the cube around a light at a point, or along a directional light
  std::vector<float> opaque;
  std::vector<float> filterDepth;
  std::vector<int> filterMaterial;
};

// The memory the maps of the scene's lights take, worked out before any is
// made: six maps for a light at a point, one for a directional light, each
// of size x size depths, and as many depths and materials again when the
// scene has a transparent material.
std::uint64_t shadowMapBytes(const Scene& scene, const ShadowMapSettings& settings);

// A depth map per face of the cube around each light of one point (a point
// light; an area light's centre), a single orthographic one for each
// directional light, made of the scene's faces; they answer the shading
// model's question of how much of a light reaches a point.
class ShadowMaps final : public LightVisibility {
 public:
  ShadowMaps(const Scene& scene, const TessellatedScene& tessellated,
             const ShadowMapSettings& settings, const Workers& workers);

  Color reaching(int light, const Vec3& position, const Vec3& normal) const override;

  // "shadow_map_texels", "shadow_map_polygons" (faces drawn into the maps),
  // "shadow_lookups" (points asked about a light) and "shadow_tests" (depth
  // comparisons, one a texel of the filter).
  void addStats(Stats& stats) const;

  // The "shadow-map" buffer: a row for each light, its maps side by side,
  // each at most kPictureSide texels a side; the raw depths, infinite where
  // a map sees nothing.
  Image picture() const;
  static constexpr int kPictureSide = 256;

 private:
  Color filterAt(const DepthMap& map, int x, int y, float depth) const;

  const Scene& scene_;
  ShadowMapSettings settings_;
  std::vector<std::vector<DepthMap>> maps_;  // by light: six cube faces, one map, or none
  std::uint64_t polygonsDrawn_ = 0;
  mutable std::atomic<std::uint64_t> lookups_{0};
  mutable std::atomic<std::uint64_t> tests_{0};
};

}  // namespace rise
