// Whitted ray tracing, after Whitted (1980), as in the original RISE report.
//
// A ray leaves the eye through each sample position of a pixel and finds the
// nearest surface it hits (Intersect). There the colour is computed (Shade):
//   - the Phong model's ambient light, and each light that a shadow ray from
//     the point reaches: an opaque shape in the way blocks it, a transparent
//     one filters it by its transmission and colour (a light whose Phong
//     terms are zero at the point sends no shadow ray);
//   - the mirror ray, reflected about the normal, traced recursively and
//     weighted by the material's `reflection`;
//   - the refracted ray, bent by Snell's law with the relative index of the
//     two sides, traced recursively, weighted by the `transmission` and
//     tinted by the colour; past the critical angle there is no refracted ray
//     and the light reflects totally, along the mirror direction.
// A ray that hits nothing takes the background colour; the recursion stops
// at the maximum depth. The rays of one pixel form a tree: each node a hit,
// its children the shadow, reflected and refracted rays, and the pixel's
// colour the sum of what every node's Phong terms add, weighted by the
// products of the weights on the way up.
//
// Whitted's ray tracer sees the scene at one instant, the shutter's opening,
// and answers every choice of a path with one ray: an area light acts as a
// point at its centre, a rough material as a smooth one. Anti-aliasing comes
// from several samples in each pixel, placed by the render's pattern, or from
// Whitted's own adaptive supersampling: a pixel's corners are traced first,
// and where their colours differ by more than a threshold the square is
// quartered and its new corners traced, down to a given depth.
#include "ray/ray_tracing.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "ray/ray_tree_builder.hpp"
#include "ray/shadow_terminator.hpp"
#include "scene/light.hpp"
#include "shading/phong.hpp"

namespace rise {

const AlgorithmDescription& WhittedRayTracer::description() const {
  static const AlgorithmDescription description = rayTracingAlgorithm(
      "ray-tracing", "Whitted ray tracing: shadows, mirror reflection and refraction, recursively",
      "T. Whitted, An improved illumination model for shaded display, CACM 23(6), 1980",
      {Effect::Shadows, Effect::Reflection, Effect::Refraction});
  return description;
}

namespace {

// Built where it is returned, not copied there: a surface point is large,
// and copying it just after the shape wrote it field by field would wait for
// those writes to reach the cache.
SurfacePoint surfaceSeen(const Ray& ray, const Hit& hit, const Material& material) {
  return material.readsTextureFrame() ? hit.shape->surfaceAt(ray, hit)
                                      : hit.shape->pointAt(ray, hit);
}

ShadingFrame shadingFrame(const Ray& ray, const Hit& hit, const Material& material) {
  ShadingFrame frame{.surface = surfaceSeen(ray, hit, material)};
  frame.surface.shadingNormal = shadingNormal(material, frame.surface);
  frame.toViewer = -glm::normalize(ray.direction);
  frame.time = ray.time;
  frame.entering = glm::dot(frame.surface.normal, frame.toViewer) > 0.0f;
  frame.normal = frame.entering ? frame.surface.normal : -frame.surface.normal;
  frame.shadingNormal = frame.entering ? frame.surface.shadingNormal : -frame.surface.shadingNormal;
  return frame;
}

// A ray leaving the surface along `direction`, started a little off the
// surface on the side it travels to, so that it does not hit it again.
Ray spawnRay(const ShadingFrame& frame, const Vec3& direction) {
  const float side = glm::dot(direction, frame.normal) >= 0.0f ? 1.0f : -1.0f;
  return Ray{frame.surface.position + (side * kRayEpsilon) * frame.normal, direction, frame.time};
}

// One ray's journey and the rays it gives rise to. When a tree is being
// recorded for a student, every ray is told to it as it is traced; the
// telling stays out of the way of a render nobody watches (an unlikely
// branch, the Phong terms it wants worked out in a function of its own).
class Recursion {
 public:
  Recursion(const TracingContext& context, PathChoices& choices, TraceCounters& counters,
            RayTreeBuilder* tree)
      : context_(context), choices_(choices), counters_(counters), tree_(tree) {}

  // Intersect: the nearest hit, shaded, or the background. `weight` is what
  // the colour it brings back will be multiplied by, for the tree.
  Color trace(const Ray& ray, int depth, RayKind kind, const Color& weight) {
    Hit hit;
    const bool found = context_.intersector.nearest(ray, 0.0f, hit, counters_.intersections);
    return follow(ray, found ? &hit : nullptr, depth, kind, weight);
  }

  // The ray once its nearest hit is known (nullptr: none): Shade there, or
  // the background.
  Color follow(const Ray& ray, const Hit* hit, int depth, RayKind kind, const Color& weight) {
    if (tree_) [[unlikely]]
      tree_->begin(kind, ray, depth, weight);
    Color color = context_.scene.image.background;
    if (hit) {
      const Material& material = context_.scene.materialOf(*hit->shape);
      const ShadingFrame frame = shadingFrame(ray, *hit, material);
      if (depth == 1)
        seen_ = {Color(0.0f), hit->t * glm::length(ray.direction), frame.surface.normal};
      if (tree_) [[unlikely]]
        tree_->hit(*hit, frame.surface);
      color = shade(frame, material, depth);
    }
    if (tree_) [[unlikely]]
      tree_->end(color);
    return color;
  }

  // What the primary ray hit, for the auxiliary buffers.
  const SampleResult& seen() const { return seen_; }

  // `color`, the local model's at the point, with the mirror and the
  // refracted rays' added.
  [[gnu::always_inline]] Color withMirrorAndGlass(Color color, const ShadingFrame& frame,
                                                  const Material& material, int depth) {
    if (depth >= context_.maxDepth) return color;
    if (material.reflection > 0.0f)
      color += spawned(RayKind::Reflection, Color(material.reflection),
                       reflectedRay(frame, material, depth), depth);
    if (material.transmission > 0.0f)
      color += spawned(RayKind::Refraction, material.transmission * material.color,
                       refractedRay(frame, material, depth), depth);
    return color;
  }

  // Calls send(light's index, shadow ray, sample, lit) for each light whose
  // shadow ray is to be traced from the point, counted: not one behind the
  // surface, nor one whose Phong terms `lit` at the point are zero (clear
  // glass has no diffuse term, and its sharp highlight is zero but near the
  // mirror direction): whatever reached the point, it would add nothing.
  template <typename Send>
  [[gnu::always_inline]] void forEachShadowRay(const ShadingFrame& frame, const Material& material,
                                               const SurfaceColors& colors, int depth,
                                               Send&& send) {
    const auto& lights = context_.scene.lights;
    for (std::size_t light = 0; light < lights.size(); ++light) {
      const LightSample sample = choices_.aimAt(*lights[light], frame.surface.position, depth);
      const std::optional<Ray> shadow =
          shadowRay(frame.surface, frame.normal, sample.toLight, frame.time);
      if (!shadow) continue;
      const Color lit = phongDirect(material, colors, frame.shadingNormal, frame.toViewer, sample);
      if (lit == Color(0.0f)) continue;
      ++counters_.shadowRays;
      send(static_cast<int>(light), *shadow, sample, lit);
    }
  }

  // What a light adds through what its shadow ray let through.
  static void addLight(Color& color, const Color& visible, const Color& lit) {
    if (visible != Color(0.0f)) color += visible * lit;
  }

 private:
  // Shade: the local Phong model, then the mirror and the refracted rays.
  Color shade(const ShadingFrame& frame, const Material& material, int depth) {
    const SurfaceColors colors = surfaceColors(material, frame.surface);
    const Color ambient = phongAmbient(material, colors, context_.scene.ambient);
    if (tree_) [[unlikely]]
      tree_->ambient(ambient);
    return withMirrorAndGlass(ambient + directLight(frame, material, colors, depth), frame,
                              material, depth);
  }

  // A reflected or refracted ray traced, times its weight.
  Color spawned(RayKind kind, const Color& weight, const Ray& ray, int depth) {
    return weight * trace(ray, depth + 1, kind, weight);
  }

  // The Phong terms of every light that a shadow ray reaches.
  Color directLight(const ShadingFrame& frame, const Material& material,
                    const SurfaceColors& colors, int depth) {
    Color color(0.0f);
    forEachShadowRay(
        frame, material, colors, depth,
        [&](int light, const Ray& shadow, const LightSample& sample, const Color& lit) {
          const Color visible = context_.intersector.transmittance(shadow, 0.0f, sample.distance,
                                                                   counters_.intersections);
          if (tree_) [[unlikely]]
            tellShadow(shadow, *context_.scene.lights[static_cast<std::size_t>(light)], sample,
                       visible, frame, material, colors);
          addLight(color, visible, lit);
        });
    return color;
  }

  // A shadow ray told to the tree, with the diffuse and specular terms of
  // its light.
  [[gnu::noinline]] void tellShadow(const Ray& shadow, const Light& light,
                                    const LightSample& sample, const Color& visible,
                                    const ShadingFrame& frame, const Material& material,
                                    const SurfaceColors& colors) {
    tree_->shadow(shadow, light, sample.distance, visible,
                  phongDirect(material, {colors.color, Color(0.0f)}, frame.shadingNormal,
                              frame.toViewer, sample),
                  phongDirect(material, {Color(0.0f), colors.ks}, frame.shadingNormal,
                              frame.toViewer, sample));
  }

  Ray reflectedRay(const ShadingFrame& frame, const Material& material, int depth) {
    ++counters_.reflectionRays;
    const Vec3 mirror = glm::reflect(-frame.toViewer, frame.shadingNormal);
    return spawnRay(frame, choices_.scatter(mirror, material.roughness, frame.normal, depth));
  }

  // Snell's law with the relative index of the two sides; past the critical
  // angle there is no refracted ray and the light reflects totally.
  Ray refractedRay(const ShadingFrame& frame, const Material& material, int depth) {
    ++counters_.refractionRays;
    const float eta = frame.entering ? 1.0f / material.ior : material.ior;
    Vec3 direction = glm::refract(-frame.toViewer, frame.shadingNormal, eta);
    if (direction == Vec3(0.0f)) direction = glm::reflect(-frame.toViewer, frame.shadingNormal);
    return spawnRay(frame, choices_.scatter(direction, material.roughness, frame.normal, depth));
  }

  const TracingContext& context_;
  PathChoices& choices_;
  TraceCounters& counters_;
  RayTreeBuilder* tree_;
  SampleResult seen_;
};

}  // namespace

LightSample SingleRayChoices::aimAt(const Light& light, const Vec3& point, int) {
  return light.illuminate(point);
}

namespace {

// A primary ray whose search of the scene found `hit` (nullptr: nothing),
// the search's cost already counted: counted, then shaded.
SampleResult shadeSearchedPrimary(const TracingContext& context, const Ray& ray, const Hit* hit,
                                  PathChoices& choices, TraceCounters& counters, RayTree* tree) {
  ++counters.primaryRays;
  return shadeFirstHit(context, ray, hit, choices, counters, tree);
}

}  // namespace

SampleResult tracePrimary(const TracingContext& context, const Ray& ray, PathChoices& choices,
                          TraceCounters& counters, RayTree* tree) {
  Hit hit;
  const bool found = context.intersector.nearest(ray, 0.0f, hit, counters.intersections);
  return shadeSearchedPrimary(context, ray, found ? &hit : nullptr, choices, counters, tree);
}

SampleResult shadeFirstHit(const TracingContext& context, const Ray& ray, const Hit* hit,
                           PathChoices& choices, TraceCounters& counters, RayTree* tree) {
  std::optional<RayTreeBuilder> builder;
  if (tree) builder.emplace(context.scene, *tree);
  Recursion recursion(context, choices, counters, builder ? &*builder : nullptr);
  const Color color = recursion.follow(ray, hit, 1, RayKind::Primary, Color(1.0f));
  if (tree) tree->color = color;
  SampleResult result = recursion.seen();
  result.color = color;
  return result;
}

FirstHitShading::FirstHitShading(const TracingContext& context, const Ray& ray, const Hit& hit,
                                 PathChoices& choices, TraceCounters& counters,
                                 std::vector<LitShadowRay>& shadowRays)
    : frame_(shadingFrame(ray, hit, context.scene.materialOf(*hit.shape))),
      material_(&context.scene.materialOf(*hit.shape)),
      seen_{Color(0.0f), hit.t * glm::length(ray.direction), frame_.surface.normal},
      firstShadowRay_(shadowRays.size()) {
  const SurfaceColors colors = surfaceColors(*material_, frame_.surface);
  ambient_ = phongAmbient(*material_, colors, context.scene.ambient);
  Recursion recursion(context, choices, counters, nullptr);
  recursion.forEachShadowRay(
      frame_, *material_, colors, 1,
      [&](int light, const Ray& shadow, const LightSample& sample, const Color& lit) {
        // Filled where it is kept: one made apart and copied in would be read
        // back just after being written field by field, which waits for the
        // writes.
        LitShadowRay& kept = shadowRays.emplace_back();
        kept.ray = shadow;
        kept.distance = sample.distance;
        kept.lit = lit;
        kept.light = light;
      });
  endOfShadowRays_ = shadowRays.size();
}

SampleResult FirstHitShading::finish(const TracingContext& context, PathChoices& choices,
                                     TraceCounters& counters,
                                     const std::vector<LitShadowRay>& shadowRays,
                                     const std::vector<Color>& visible) const {
  Color direct(0.0f);
  for (std::size_t i = firstShadowRay_; i < endOfShadowRays_; ++i)
    Recursion::addLight(direct, visible[i], shadowRays[i].lit);
  Recursion recursion(context, choices, counters, nullptr);
  SampleResult result = seen_;
  result.color = recursion.withMirrorAndGlass(ambient_ + direct, frame_, *material_, 1);
  return result;
}

namespace {

float largestDifference(const std::array<Color, 4>& corners) {
  float largest = 0.0f;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      largest = std::max(largest, maxComponent(glm::abs(corners[i] - corners[j])));
  return largest;
}

// Adaptive supersampling of one square of the image: the average of its
// corners if they agree, or else of its four quarters, each refined in turn,
// down to `levelsLeft` more subdivisions. Corners are ordered top-left,
// top-right, bottom-left, bottom-right.
class AdaptiveRefinement {
 public:
  AdaptiveRefinement(const TraceAt& traceAt, float threshold, Rng& rng, TraceCounters& counters)
      : traceAt_(traceAt), threshold_(threshold), rng_(rng), counters_(counters) {}

  Color refine(const Vec2& topLeft, float size, const std::array<Color, 4>& corners,
               int levelsLeft) {
    if (levelsLeft == 0 || largestDifference(corners) <= threshold_)
      return 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
    refined_ = true;
    const float half = 0.5f * size;
    const Color top = colorAt(topLeft + Vec2(half, 0.0f));
    const Color left = colorAt(topLeft + Vec2(0.0f, half));
    const Color centre = colorAt(topLeft + Vec2(half, half));
    const Color right = colorAt(topLeft + Vec2(size, half));
    const Color bottom = colorAt(topLeft + Vec2(half, size));
    const int next = levelsLeft - 1;
    return 0.25f *
           (refine(topLeft, half, {corners[0], top, left, centre}, next) +
            refine(topLeft + Vec2(half, 0.0f), half, {top, corners[1], centre, right}, next) +
            refine(topLeft + Vec2(0.0f, half), half, {left, centre, corners[2], bottom}, next) +
            refine(topLeft + Vec2(half, half), half, {centre, right, bottom, corners[3]}, next));
  }

  bool refined() const { return refined_; }

 private:
  Color colorAt(const Vec2& raster) { return traceAt_(raster, rng_, counters_, nullptr).color; }

  const TraceAt& traceAt_;
  float threshold_;
  Rng& rng_;
  TraceCounters& counters_;
  bool refined_ = false;
};

// The subdivisions that `samples` allow: 16 samples, two levels of quarters.
int adaptiveLevels(int samples) {
  int levels = 0;
  for (int cells = 1; cells < samples; cells *= 4) ++levels;
  return levels;
}

}  // namespace

// The tile's pixel corners are traced once each, shared by the pixels around
// them; each pixel then refines its own square.
void sampleAdaptively(TileTrace& tile, const RenderSettings& settings, const TraceAt& traceAt) {
  const PixelRect& area = tile.area();
  TraceCounters& counters = tile.counters;
  std::vector<SampleResult> corners;
  std::vector<std::uint64_t> cornerTests;
  for (int y = area.y0; y <= area.y1; ++y) {
    for (int x = area.x0; x <= area.x1; ++x) {
      Rng rng(pixelSeed(settings.seed, x, y), 1);
      const std::uint64_t testsBefore = counters.intersections.tests;
      corners.push_back(
          traceAt(Vec2(static_cast<float>(x), static_cast<float>(y)), rng, counters, nullptr));
      cornerTests.push_back(counters.intersections.tests - testsBefore);
    }
  }
  const auto corner = [&](int x, int y) {
    return static_cast<std::size_t>(y - area.y0) * (area.width() + 1) + (x - area.x0);
  };
  const int levels = adaptiveLevels(settings.sampling.samples);
  for (int y = area.y0; y < area.y1 && !tile.cancelled(); ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      Rng rng(pixelSeed(settings.seed, x, y), 2);
      const std::uint64_t testsBefore = counters.intersections.tests;
      AdaptiveRefinement refinement(traceAt, settings.sampling.adaptiveThreshold, rng, counters);
      const Color color =
          refinement.refine(Vec2(static_cast<float>(x), static_cast<float>(y)), 1.0f,
                            {corners[corner(x, y)].color, corners[corner(x + 1, y)].color,
                             corners[corner(x, y + 1)].color, corners[corner(x + 1, y + 1)].color},
                            levels);
      tile.addSample({x, y}, Vec2(0.5f), color);
      if (refinement.refined()) ++tile.refinedPixels;
      tile.recordBuffers({x, y}, corners[corner(x, y)],
                         cornerTests[corner(x, y)] + counters.intersections.tests - testsBefore);
    }
  }
}

namespace {

// The primary hits of a row of a tile, found a packet of rays at a time
// (bvh.hpp) before the row is shaded. Where every pixel places its samples
// alike, a row's samples in order lie side by side and their rays are
// coherent: eight neighbouring pixels' centres, or the grid of one or two.
class RowOfPrimaryHits {
 public:
  // `offsets`: where every pixel of the tile places its samples.
  RowOfPrimaryHits(const TracingContext& context, const ViewFrame& view, const PixelRect& area,
                   const std::vector<Vec2>& offsets)
      : context_(context), view_(view), area_(area), offsets_(offsets) {}

  // Sample i of the pixel traced as tracePrimary traces it, from the hit
  // found with the rest of its row's.
  SampleResult trace(const glm::ivec2& pixel, int i, TraceCounters& counters, RayTree* tree) {
    if (pixel.y != row_) findHits(pixel.y);
    const std::size_t sample = static_cast<std::size_t>(pixel.x - area_.x0) * offsets_.size() +
                               static_cast<std::size_t>(i);
    const RayPacket& packet = packets_[sample / kPacketSize];
    const std::size_t lane = sample % kPacketSize;
    counters.intersections += packet.costs[lane];
    SingleRayChoices single;
    return shadeSearchedPrimary(context_, packet.rays[lane],
                                packet.found[lane] ? &packet.hits[lane] : nullptr, single, counters,
                                tree);
  }

 private:
  void findHits(int y) {
    row_ = y;
    packets_.clear();
    for (int x = area_.x0; x < area_.x1; ++x) {
      for (const Vec2& offset : offsets_) {
        if (packets_.empty() || packets_.back().size == kPacketSize) packets_.emplace_back();
        RayPacket& packet = packets_.back();
        const Vec2 raster = Vec2(glm::ivec2(x, y)) + offset;
        packet.rays[static_cast<std::size_t>(packet.size++)] = view_.primaryRay(raster.x, raster.y);
      }
    }
    for (RayPacket& packet : packets_) context_.intersector.nearestOfPacket(packet, 0.0f);
  }

  const TracingContext& context_;
  const ViewFrame& view_;
  PixelRect area_;
  const std::vector<Vec2>& offsets_;
  int row_ = -1;
  std::vector<RayPacket> packets_;
};

}  // namespace

RenderResult WhittedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                      RenderObserver& observer) const {
  const SceneIntersector intersector(scene, settings.accel, settings.threads);
  const TracingContext context{scene, intersector, settings.maxDepth};
  const ViewFrame view(scene.camera, settings.width, settings.height);
  const TraceAt traceAt = [&](const Vec2& raster, Rng&, TraceCounters& counters, RayTree* tree) {
    SingleRayChoices single;
    return tracePrimary(context, view.primaryRay(raster.x, raster.y), single, counters, tree);
  };
  const PixelSampling& sampling = settings.sampling;
  RenderResult result = traceImage(settings, observer, [&](TileTrace& tile) {
    if (sampling.pattern == SamplePattern::Adaptive)
      return sampleAdaptively(tile, settings, traceAt);
    std::vector<Vec2> offsets;
    const auto place = [&](const glm::ivec2&, Rng& rng) -> const std::vector<Vec2>& {
      samplePositions(sampling.pattern, sampling.samples, rng, offsets);
      return offsets;
    };
    if (placesAlikeInEveryPixel(sampling.pattern)) {
      RowOfPrimaryHits row(context, view, tile.area(), offsets);
      return tracePixels(tile, settings.seed, place,
                         [&](const glm::ivec2& pixel, int i, Rng&, TraceCounters& counters,
                             RayTree* tree) { return row.trace(pixel, i, counters, tree); });
    }
    tracePixels(
        tile, settings.seed, place,
        [&](const glm::ivec2& pixel, int i, Rng& rng, TraceCounters& counters, RayTree* tree) {
          return traceAt(Vec2(pixel) + offsets[static_cast<std::size_t>(i)], rng, counters, tree);
        });
  });
  intersector.addBuildStats(result.stats);
  return result;
}

}  // namespace rise
