// Shadow maps, after Williams (L. Williams, "Casting curved shadows on curved
// surfaces", SIGGRAPH 1978), with percentage-closer filtering (W. T. Reeves,
// D. H. Salesin and R. L. Cook, "Rendering antialiased shadows with depth
// maps", SIGGRAPH 1987).
//
// A point is in shadow when something lies between it and the light. Before
// the image is made, the scene is drawn from each light with a z-buffer that
// keeps depths alone: the depth map holds, for each texel, how far from the
// light the nearest surface is. A point light sees all around it, so it gets
// six maps, the faces of a cube (90-degree views along +-x, +-y, +-z); a
// directional light, from infinitely far, an orthographic map along its
// direction around the scene's finite shapes. Shading a point then asks the
// map: the point is carried into the light's view, and if it lies farther
// than the depth stored at its texel, something nearer to the light hides it.
//
// The bias: the map samples the surfaces at texel centres, the point asking
// lies anywhere in a texel, and on a surface tilted by theta from the light
// the depth changes by a texel's side times tan(theta) across a texel; without
// a margin, lit surfaces shadow themselves in stripes ("shadow acne"). The
// point is compared with the stored depth plus a bias of `bias` texels, scaled
// by the slope (1 + (r + 1/2) tan theta, for a filter r texels wide): too
// little and the acne shows, too much and shadows come loose from the objects
// that cast them ("peter panning"). --shadow-bias shows both.
//
// Percentage-closer filtering: filtering depths would average a near and a far
// surface into a depth that is neither; Reeves, Salesin and Cook filter the
// answers instead, comparing the point with each texel of a (2 r + 1)^2 square
// around its own and taking the lit fraction, which softens the map's
// staircase into a ramp a few texels wide.
//
// Transparent surfaces are kept apart: the map holds the nearest opaque depth
// and the nearest transparent surface in front of it, whose transmission times
// colour filters the light, as a shadow ray through one transparent shape is
// filtered by Whitted's ray tracer.
#include "raster/shadow_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/warps.hpp"

namespace rise {

namespace {

constexpr float kInfiniteDepth = kInfinity;
// Near the terminator tan(theta) grows without bound; the bias stops growing
// where the surface is this steep from the light, a floor seen 89.9 degrees
// from the light on the horizon of a map still far from it.
constexpr float kSteepestSlope = 1000.0f;

// Around the scene's finite shapes (planes reach to the horizon and cast
// nothing that matters there), along the light's direction `travel`.
std::vector<AxisView> orthographicView(const TessellatedScene& tessellated, const Scene& scene,
                                       const Vec3& travel, int size) {
  std::vector<bool> finite;
  for (const auto& shape : scene.shapes) finite.push_back(shape->bounds().isFinite());
  Bounds3 bounds;
  for (const SceneFace& face : tessellated.faces)
    if (finite[static_cast<std::size_t>(face.shape)])
      for (int vertex : face.vertices) bounds.grow(tessellated.vertices[vertex].position);
  if (bounds.isEmpty()) return {};
  const Vec3 centre = 0.5f * (bounds.min + bounds.max);
  const float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
  Vec3 right, up;
  orthonormalBasis(travel, right, up);
  return {{centre - 2.0f * radius * travel, right, up, travel, false, radius, size}};
}

bool hasTransparentFaces(const Scene& scene, const TessellatedScene& tessellated) {
  return std::any_of(
      tessellated.faces.begin(), tessellated.faces.end(),
      [&](const SceneFace& face) { return scene.materials[face.material].isTransparent(); });
}

// Draws the scene's faces into one map; returns the number of faces that
// reached it.
std::uint64_t drawDepths(const Scene& scene, const TessellatedScene& tessellated, DepthMap& map) {
  const AxisView& view = map.view;
  PolygonInView polygon;
  std::uint64_t drawn = 0;
  for (const SceneFace& face : tessellated.faces) {
    const std::array<Vec3, 3> corners = {tessellated.vertices[face.vertices[0]].position,
                                         tessellated.vertices[face.vertices[1]].position,
                                         tessellated.vertices[face.vertices[2]].position};
    if (!polygon.project(view, corners)) continue;
    ++drawn;
    const bool transparent = scene.materials[face.material].isTransparent();
    polygon.forEachTexel(view.whole(), [&](int x, int y, float depth) {
      const std::size_t texel = static_cast<std::size_t>(y) * view.size + x;
      if (!transparent) {
        map.opaque[texel] = std::min(map.opaque[texel], depth);
      } else if (depth < map.filterDepth[texel]) {
        map.filterDepth[texel] = depth;
        map.filterMaterial[texel] = face.material;
      }
    });
  }
  return drawn;
}

}  // namespace

std::uint64_t shadowMapBytes(const Scene& scene, const ShadowMapSettings& settings) {
  const bool transparency =
      std::any_of(scene.materials.begin(), scene.materials.end(),
                  [](const Material& material) { return material.isTransparent(); });
  const auto texels = static_cast<std::uint64_t>(settings.size) * settings.size;
  std::uint64_t bytes = 0;
  for (const auto& light : scene.lights) {
    const bool atAPoint = std::isfinite(light->illuminate(Vec3(0.0f)).distance);
    bytes += (atAPoint ? 6 : 1) * texels *
             (sizeof(float) + (transparency ? sizeof(float) + sizeof(int) : 0));
  }
  return bytes;
}

ShadowMaps::ShadowMaps(const Scene& scene, const TessellatedScene& tessellated,
                       const ShadowMapSettings& settings, const Workers& workers)
    : scene_(scene), settings_(settings) {
  const bool transparency = hasTransparentFaces(scene, tessellated);
  for (const auto& light : scene.lights) {
    const LightSample fromOrigin = light->illuminate(Vec3(0.0f));
    const std::vector<AxisView> views =
        std::isfinite(fromOrigin.distance)
            ? cubeViews(fromOrigin.toLight * fromOrigin.distance, settings.size)
            : orthographicView(tessellated, scene, -fromOrigin.toLight, settings.size);
    std::vector<DepthMap>& maps = maps_.emplace_back();
    const std::size_t texels = static_cast<std::size_t>(settings.size) * settings.size;
    for (const AxisView& view : views) {
      maps.push_back({view, std::vector<float>(texels, kInfiniteDepth), {}, {}});
      if (!transparency) continue;
      maps.back().filterDepth.assign(texels, kInfiniteDepth);
      maps.back().filterMaterial.assign(texels, -1);
    }
  }
  std::vector<DepthMap*> all;
  for (std::vector<DepthMap>& maps : maps_)
    for (DepthMap& map : maps) all.push_back(&map);
  polygonsDrawn_ = workers.sumOverTasks<std::uint64_t>(
      static_cast<int>(all.size()),
      [&](int map, std::uint64_t& drawn) { drawn += drawDepths(scene, tessellated, *all[map]); });
}

// What one texel lets through to a point at `depth` plus its bias.
Color ShadowMaps::filterAt(const DepthMap& map, int x, int y, float depth) const {
  const std::size_t texel = static_cast<std::size_t>(y) * map.view.size + x;
  if (depth > map.opaque[texel]) return Color(0.0f);
  if (map.filterDepth.empty() || depth <= map.filterDepth[texel]) return Color(1.0f);
  const Material& filter = scene_.materials[map.filterMaterial[texel]];
  return filter.transmission * filter.color;
}

Color ShadowMaps::reaching(int light, const Vec3& position, const Vec3& normal) const {
  const std::vector<DepthMap>& maps = maps_[static_cast<std::size_t>(light)];
  if (maps.empty()) return Color(1.0f);
  const DepthMap& map =
      maps.size() == 1 ? maps[0]
                       : maps[static_cast<std::size_t>(cubeFaceOf(position - maps[0].view.origin))];
  const AxisView& view = map.view;
  const Vec3 seen = view.toView(position);
  if (view.perspective && seen.z <= kAxisViewNear) return Color(1.0f);
  const Vec2 onMap = view.toMap(seen);
  const float size = static_cast<float>(view.size);
  // Outside an orthographic map no finite shape casts a shadow; a cube face
  // holds every point it is chosen for, but for rounding at its sides.
  if (!view.perspective &&
      !(onMap.x >= 0.0f && onMap.y >= 0.0f && onMap.x < size && onMap.y < size))
    return Color(1.0f);
  ++lookups_;

  const Vec3 toLight = view.perspective ? glm::normalize(view.origin - position) : -view.forward;
  const float cosine = std::max(std::abs(glm::dot(normal, toLight)), 1e-6f);
  const float slope =
      std::min(std::sqrt(std::max(0.0f, 1.0f - cosine * cosine)) / cosine, kSteepestSlope);
  const int radius = settings_.filterRadius;
  // Off a cube face's axis a texel spreads wider, by the squared ratio of
  // the distance to the depth along the axis (up to 3, in the corners).
  const float spread = view.perspective ? glm::dot(seen, seen) / (seen.z * seen.z) : 1.0f;
  const float bias = settings_.bias * view.texelSize(seen.z) * spread *
                     (1.0f + (static_cast<float>(radius) + 0.5f) * slope);
  const int centreX = std::clamp(static_cast<int>(onMap.x), 0, view.size - 1);
  const int centreY = std::clamp(static_cast<int>(onMap.y), 0, view.size - 1);
  Color passed(0.0f);
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      passed += filterAt(map, std::clamp(centreX + dx, 0, view.size - 1),
                         std::clamp(centreY + dy, 0, view.size - 1), seen.z - bias);
  const int taps = (2 * radius + 1) * (2 * radius + 1);
  tests_ += static_cast<std::uint64_t>(taps);
  return passed / static_cast<float>(taps);
}

void ShadowMaps::addStats(Stats& stats) const {
  std::uint64_t texels = 0;
  for (const std::vector<DepthMap>& maps : maps_)
    for (const DepthMap& map : maps) texels += map.opaque.size();
  stats.add("shadow_map_texels", static_cast<double>(texels));
  stats.add("shadow_map_polygons", static_cast<double>(polygonsDrawn_));
  stats.add("shadow_lookups", static_cast<double>(lookups_.load()));
  stats.add("shadow_tests", static_cast<double>(tests_.load()));
}

Image ShadowMaps::picture() const {
  const int side = std::min(settings_.size, kPictureSide);
  std::size_t mostMaps = 1;
  for (const std::vector<DepthMap>& maps : maps_) mostMaps = std::max(mostMaps, maps.size());
  Image image(static_cast<int>(mostMaps) * side, std::max(1, static_cast<int>(maps_.size())) * side,
              Color(kInfiniteDepth));
  for (std::size_t light = 0; light < maps_.size(); ++light)
    for (std::size_t m = 0; m < maps_[light].size(); ++m) {
      const DepthMap& map = maps_[light][m];
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
          const int texelX = (2 * x + 1) * settings_.size / (2 * side);
          const int texelY = (2 * y + 1) * settings_.size / (2 * side);
          image.at(static_cast<int>(m) * side + x, static_cast<int>(light) * side + y) =
              Color(map.opaque[static_cast<std::size_t>(texelY) * settings_.size + texelX]);
        }
    }
  return image;
}

}  // namespace rise
