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
// Whitted's own adaptive supersampling (adaptive_supersampling.hpp): a
// pixel's corners are traced first, and where their colours differ by more
// than a threshold the square is quartered and its new corners traced, down
// to a given depth. Where every pixel places its samples alike, their
// primary rays go through the scene a packet at a time (primary_packets.hpp).
#include "ray/ray_tracing.hpp"

#include <optional>
#include <vector>

#include "ray/primary_packets.hpp"
#include "ray/ray_tree_builder.hpp"
#include "ray/shadow_terminator.hpp"
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
    const Color ambient = phongUnlit(material, colors, context_.scene.ambient);
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

SampleResult shadeSearchedPrimary(const TracingContext& context, const Ray& ray, const Hit* hit,
                                  PathChoices& choices, TraceCounters& counters, RayTree* tree) {
  ++counters.primaryRays;
  return shadeFirstHit(context, ray, hit, choices, counters, tree);
}

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
  ambient_ = phongUnlit(*material_, colors, context.scene.ambient);
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

// A pixel's samples, each traced by a primary ray and the recursion from
// its hit; a packet of primary rays at a time where every pixel places its
// samples alike.
RenderResult WhittedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                      RenderObserver& observer) const {
  return traceTiles(scene, settings, observer, [&](const TracingContext& context, TileTrace& tile) {
    if (placesAlikeInEveryPixel(settings.sampling.pattern))
      return traceInPrimaryPackets(context, tile, settings);
    traceEachSample(tile, settings, {},
                    [&](const Vec2& raster, SampleValues&, TraceCounters& counters, RayTree* tree) {
                      SingleRayChoices single;
                      return tracePrimary(context, context.view.primaryRay(raster.x, raster.y),
                                          single, counters, tree);
                    });
  });
}

}  // namespace rise
