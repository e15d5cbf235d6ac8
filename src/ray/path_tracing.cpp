// Path tracing, after Kajiya, "The rendering equation" (SIGGRAPH 1986).
//
// The light leaving a point x towards the eye is what x emits and what it
// reflects of the light arriving from every direction:
//   L(x, wo) = Le(x, wo) + integral over the hemisphere of f(x, wi, wo) L(y, -wi) cos(theta_i) dwi,
// y being the surface seen from x along wi: the rendering equation, whose
// unknown L is on both sides. Whitted's and Cook's ray tracers follow only the
// few directions where f is a spike (mirrors, glass) and the lights; the
// equation's other terms, the light surfaces give one another, they replace
// by an ambient constant. A path tracer estimates the whole integral by Monte
// Carlo: at each surface a path meets it takes ONE direction wi, at random
// with a density p, and multiplies what comes back along it by f cos / p.
// The average of many such paths per pixel converges to the true L: colour
// bleeding, soft shadows, caustics, all from the same few lines.
//
// Three refinements make it practical:
//   next-event estimation: a path rarely hits a small light by chance, so at
//     each vertex a shadow ray goes to a point chosen on the lights
//     (emitters.hpp) and adds its light directly;
//   multiple importance sampling (Veach and Guibas, SIGGRAPH 1995): a light
//     is then found two ways, by its shadow ray and by a direction the BRDF
//     sampled that hits it. Each counts with the power heuristic's weight
//     p_a^2 / (p_a^2 + p_b^2), its own density against the other's, so that
//     each way counts most where it is the better (a shadow ray for a small
//     light on a rough surface, the BRDF's sample for a large light on a
//     shiny one) and the two add up to the light once;
//   Russian roulette (Arvo and Kirk, SIGGRAPH 1990): past the third vertex a
//     path goes on with a probability q, the largest channel of the weight it
//     carries, and is divided by q when it does: it ends where it would bring
//     back little, and the estimate stays unbiased.
// `--light-sampling nee|brdf|mis` keeps one way or both, `--no-roulette`
// follows every path to `--max-depth`, so that a student sees what each buys.
//
// The surfaces scatter light as shading/scattering.hpp says, from the same
// material keys as every other algorithm; the lights are the surfaces whose
// material has an `emission`, the background (the light of rays that leave
// the scene), and the scene's lights of the classic model, which give a
// surface facing them the irradiance pi times their colour at any distance,
// so that a white diffuse surface under them looks as it does in Phong's
// model; no ray can hit them, so their shadow rays alone find them, as in the
// other ray tracers, through what transparent surfaces let through. The image
// is refined pass after pass, each a few samples a pixel with seeds of its
// own, until the samples, the time or the noise asked for is reached.
#include "ray/path_tracing.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "ray/emitters.hpp"
#include "ray/progressive.hpp"
#include "ray/ray_tree_builder.hpp"
#include "ray/shading_frame.hpp"
#include "ray/shadow_terminator.hpp"
#include "shading/scattering.hpp"

namespace rise {

const AlgorithmDescription& PathTracer::description() const {
  static const AlgorithmDescription description = [] {
    AlgorithmDescription path = rayTracingAlgorithm(
        "path-tracing",
        "Kajiya's path tracing: the rendering equation by Monte Carlo, light between all surfaces",
        "J. T. Kajiya, The rendering equation, SIGGRAPH 1986",
        {Effect::Shadows, Effect::Reflection, Effect::Refraction, Effect::SoftShadows,
         Effect::IndirectLight});
    path.buffers.push_back("variance");
    path.options.push_back(Option::LightSampling);
    path.options.push_back(Option::Progression);
    return path;
  }();
  return description;
}

RenderNeeds PathTracer::needs(const Scene& scene, const RenderSettings& settings) const {
  RenderNeeds needs = RayTracer::needs(scene, passSettings(settings, 0));
  // A path's vertex traces its ray on, a shadow ray to the emitters and one
  // to each light of the classic model.
  needs.rays = static_cast<double>(settings.area().width()) * settings.area().height() *
               settings.progression.samples * settings.maxDepth *
               (2.0 + static_cast<double>(scene.lights.size()));
  needs.bytes += static_cast<std::uint64_t>(settings.width) * settings.height * kPassBytesPerPixel;
  needs.raysBranch = false;
  return needs;
}

namespace {

// What the paths did, beyond the rays they traced.
struct PathCounters {
  std::uint64_t paths = 0;
  std::uint64_t vertices = 0;  // the eye's ray's hit and every bounce's, escaped rays included
  std::uint64_t escaped = 0;   // rays that left the scene, taking the background's light
  std::uint64_t emitterShadowRays = 0;
  std::uint64_t rouletteEnded = 0;
  // The histogram of the paths' lengths: of 1, 2, ... vertices, the last
  // bin holding the paths of that many or more.
  static constexpr std::size_t kLengthBins = 8;
  std::array<std::uint64_t, kLengthBins> pathsOfLength{};

  void countPath(std::uint64_t pathVertices) {
    ++pathsOfLength[std::min<std::uint64_t>(pathVertices, kLengthBins) - 1];
  }
  PathCounters& operator+=(const PathCounters& other) {
    paths += other.paths;
    vertices += other.vertices;
    escaped += other.escaped;
    emitterShadowRays += other.emitterShadowRays;
    rouletteEnded += other.rouletteEnded;
    for (std::size_t bin = 0; bin < kLengthBins; ++bin)
      pathsOfLength[bin] += other.pathsOfLength[bin];
    return *this;
  }
  void addTo(Stats& stats) const {
    stats.add("paths", static_cast<double>(paths));
    stats.add("path_vertices", static_cast<double>(vertices));
    stats.add("vertices_per_path",
              perEach(static_cast<double>(vertices), static_cast<double>(paths)));
    stats.add("paths_escaped", static_cast<double>(escaped));
    stats.add("emitter_shadow_rays", static_cast<double>(emitterShadowRays));
    stats.add("roulette_terminations", static_cast<double>(rouletteEnded));
    for (std::size_t bin = 0; bin < kLengthBins; ++bin)
      stats.add("paths_of_" + std::to_string(bin + 1) +
                    (bin + 1 == kLengthBins ? "_or_more_vertices"
                     : bin == 0             ? "_vertex"
                                            : "_vertices"),
                static_cast<double>(pathsOfLength[bin]));
  }
};

// The power heuristic with exponent 2 for a sample of density `chosen` that
// another way would have chosen with density `other`. As a ratio, so that a
// density too large for a float (a light seen edge on) weighs 1 or 0, not NaN.
float powerHeuristic(float chosen, float other) {
  if (chosen <= 0.0f) return 0.0f;
  const float ratio = other / chosen;
  return 1.0f / (1.0f + ratio * ratio);
}

// How the path arrived at a surface: its density, per steradian, if a BRDF
// sample spread over directions chose its ray, which multiple importance
// sampling weighs the surface's emission by; none for the eye's ray and
// for a mirror's or glass's.
struct Arrival {
  std::optional<float> spreadDensity;
  Vec3 from{0.0f};
};

// One path of a sample, from the eye, as a recursion over its vertices: the
// light coming back along `ray`.
class Path {
 public:
  Path(const TracingContext& context, const Emitters& emitters, const RenderSettings& settings,
       SampleValues& values, TraceCounters& counters, PathCounters& paths, RayTreeBuilder* tree)
      : context_(context),
        emitters_(emitters),
        settings_(settings),
        values_(values),
        counters_(counters),
        paths_(paths),
        tree_(tree) {}

  SampleResult traceFromEye(const Ray& ray) {
    ++counters_.primaryRays;
    ++paths_.paths;
    const std::uint64_t verticesBefore = paths_.vertices;
    SampleResult result;
    result.color = radiance(ray, 1, RayKind::Primary, Color(1.0f), {}, &result);
    paths_.countPath(paths_.vertices - verticesBefore);
    return result;
  }

 private:
  // L along `ray`, whose path so far carries `throughput`: the product of
  // the weights f cos / p on the way, for the roulette.
  Color radiance(const Ray& ray, int depth, RayKind kind, const Color& throughput,
                 const Arrival& arrival, SampleResult* seen) {
    ++paths_.vertices;
    if (tree_) [[unlikely]]
      tree_->begin(kind, ray, depth, throughput);
    Hit hit;
    Color color = context_.scene.image.background;
    if (context_.intersector.nearest(ray, 0.0f, hit, counters_.intersections)) {
      const Material& material = context_.scene.materialOf(*hit.shape);
      const ShadingFrame frame = shadingFrame(ray, hit, material);
      if (seen) *seen = {Color(0.0f), hit.t * glm::length(ray.direction), frame.surface.normal};
      if (tree_) [[unlikely]]
        tree_->hit(hit, frame.surface);
      const Color light = emitted(*hit.shape, material, frame, arrival);
      if (tree_) [[unlikely]]
        tree_->pathVertex().emitted = light;
      color = light + scattered(frame, material, depth, throughput);
    } else {
      ++paths_.escaped;
    }
    if (tree_) [[unlikely]]
      tree_->end(color);
    return color;
  }

  // Le, counted with the weight multiple importance sampling gives the BRDF's
  // sample against a shadow ray's; in full where no shadow ray could have
  // found it.
  Color emitted(const Shape& shape, const Material& material, const ShadingFrame& frame,
                const Arrival& arrival) const {
    if (!material.emits() || !arrival.spreadDensity) return material.emission;
    const float areaDensity = emitters_.areaDensity(shape, material.emission);
    if (areaDensity == 0.0f) return material.emission;
    switch (settings_.lightSampling) {
      case LightSampling::Brdf:
        return material.emission;
      case LightSampling::Lights:
        return Color(0.0f);
      case LightSampling::Both:
        break;
    }
    const Vec3 offset = frame.surface.position - arrival.from;
    const float lightDensity = areaDensity * glm::dot(offset, offset) /
                               std::abs(glm::dot(frame.normal, glm::normalize(offset)));
    const float weight = powerHeuristic(*arrival.spreadDensity, lightDensity);
    if (tree_) [[unlikely]]
      tree_->pathVertex().emittedWeight = weight;
    return material.emission * weight;
  }

  // The integral: the lights by shadow rays, then one direction sampled from
  // the BRDF and the light coming back along it.
  Color scattered(const ShadingFrame& frame, const Material& material, int depth,
                  const Color& throughput) {
    if (depth >= settings_.maxDepth) return Color(0.0f);
    const Scattering scattering(material, surfaceColors(material, frame.surface),
                                frame.shadingNormal, frame.toViewer, frame.entering);
    Color color(0.0f);
    if (scattering.spreads() && settings_.lightSampling != LightSampling::Brdf)
      color += classicLights(frame, scattering) + emitterLight(frame, scattering);
    const std::optional<ScatteringSample> sample =
        scattering.sample(values_.next2D(), values_.next1D());
    if (!sample || sample->weight == Color(0.0f)) return color;
    if (tree_) [[unlikely]] {
      PathVertex& vertex = tree_->pathVertex();
      vertex.density = sample->pdf;
      vertex.singular = sample->singular;
    }
    Color weight = sample->weight;
    if (settings_.russianRoulette && depth >= kRouletteFromDepth) {
      const float survival = std::min(1.0f, maxComponent(weight) * maxComponent(throughput));
      const bool ends = values_.next1D() >= survival;
      if (tree_) [[unlikely]] {
        PathVertex& vertex = tree_->pathVertex();
        vertex.survival = survival;
        vertex.endedByRoulette = ends;
      }
      if (ends) {
        ++paths_.rouletteEnded;
        return color;
      }
      weight /= survival;
    }
    ++(sample->refracted ? counters_.refractionRays : counters_.reflectionRays);
    const Arrival arrival{sample->singular ? std::nullopt : std::optional(sample->pdf),
                          frame.surface.position};
    const RayKind kind = sample->refracted ? RayKind::Refraction : RayKind::Reflection;
    return color + weight * radiance(spawnRay(frame, sample->direction), depth + 1, kind,
                                     throughput * weight, arrival, nullptr);
  }

  // Each light of the classic model, through what its shadow ray lets pass.
  Color classicLights(const ShadingFrame& frame, const Scattering& scattering) {
    Color color(0.0f);
    for (const auto& light : context_.scene.lights) {
      const LightSample sample = light->illuminate(frame.surface.position, values_.next2D());
      const float cosine = glm::dot(frame.shadingNormal, sample.toLight);
      if (cosine <= 0.0f) continue;
      const std::optional<Ray> shadow =
          shadowRay(frame.surface, frame.normal, sample.toLight, frame.time);
      if (!shadow) continue;
      const Color f = scattering.brdf(sample.toLight);
      if (f == Color(0.0f)) continue;
      ++counters_.shadowRays;
      const Color visible = context_.intersector.transmittance(*shadow, 0.0f, sample.distance,
                                                               counters_.intersections);
      const Color lit = f * sample.color * (kPi * cosine);
      if (tree_) [[unlikely]]
        tree_->shadow(*shadow, *light, sample.distance, visible, lit, Color(0.0f));
      color += visible * lit;
    }
    return color;
  }

  // A point chosen on the emitters, its light weighted against the BRDF's
  // chance of finding it.
  Color emitterLight(const ShadingFrame& frame, const Scattering& scattering) {
    if (emitters_.empty()) return Color(0.0f);
    const EmitterPoint point = emitters_.sample(values_.next1D(), values_.next2D());
    const Vec3 offset = point.position - frame.surface.position;
    const float distanceSquared = glm::dot(offset, offset);
    const float distance = std::sqrt(distanceSquared);
    const Vec3 toLight = offset / distance;
    const float cosine = glm::dot(frame.shadingNormal, toLight);
    const float cosAtLight = std::abs(glm::dot(point.normal, toLight));
    if (cosine <= 0.0f || cosAtLight <= 0.0f) return Color(0.0f);
    const std::optional<Ray> shadow = shadowRay(frame.surface, frame.normal, toLight, frame.time);
    if (!shadow) return Color(0.0f);
    const Color f = scattering.brdf(toLight);
    if (f == Color(0.0f)) return Color(0.0f);
    ++counters_.shadowRays;
    ++paths_.emitterShadowRays;
    const bool blocked = isBlocked(*shadow, distance);
    const float lightDensity = point.areaDensity * distanceSquared / cosAtLight;
    const float weight = settings_.lightSampling == LightSampling::Both
                             ? powerHeuristic(lightDensity, scattering.pdf(toLight))
                             : 1.0f;
    const Color lit = f * point.radiance * (cosine / lightDensity);
    if (tree_) [[unlikely]]
      tree_->emitterShadow(*shadow, distance, !blocked, lit, weight);
    return blocked ? Color(0.0f) : lit * weight;
  }

  // Whether any surface lies between the shadow ray's start and the point
  // `distance` away on an emitter: glass too, whose light the BRDF's samples
  // bring through it.
  bool isBlocked(const Ray& shadow, float distance) {
    Hit hit;
    hit.t = distance * (1.0f - kShadowRayShortening);
    return context_.intersector.nearest(shadow, 0.0f, hit, counters_.intersections);
  }

  static constexpr int kRouletteFromDepth = 3;
  // Short of the emitter's point by this share, so as not to hit the emitter.
  static constexpr float kShadowRayShortening = 1e-3f;

  const TracingContext& context_;
  const Emitters& emitters_;
  const RenderSettings& settings_;
  SampleValues& values_;
  TraceCounters& counters_;
  PathCounters& paths_;
  RayTreeBuilder* tree_;
};

// The first vertex's shadow rays and direction are stratified over the
// pixel's samples; deeper vertices draw fresh random values.
constexpr SampleLayout kPathLayout{.squares = 3, .intervals = 2};

}  // namespace

RenderResult PathTracer::render(const Scene& scene, const RenderSettings& settings,
                                RenderObserver& observer) const {
  return renderWithRays(scene, settings, [&](const TracingContext& context) {
    const Emitters emitters(scene);
    PathCounters total;
    std::mutex totalGuard;
    RenderResult result = renderProgressively(
        settings, observer, [&](const RenderSettings& pass, ProgressivePass& progress) {
          return traceImage(pass, progress.observer(), [&](TileTrace& tile) {
            PathCounters paths;
            traceEachSample(tile, pass, kPathLayout,
                            [&](const Vec2& raster, SampleValues& values, TraceCounters& counters,
                                RayTree* tree) {
                              std::optional<RayTreeBuilder> builder;
                              if (tree) builder.emplace(scene, *tree);
                              Path path(context, emitters, settings, values, counters, paths,
                                        builder ? &*builder : nullptr);
                              const SampleResult sample =
                                  path.traceFromEye(context.view.primaryRay(raster.x, raster.y));
                              if (tree) tree->color = sample.color;
                              progress.addSample(raster, sample.color);
                              return sample;
                            });
            const std::lock_guard lock(totalGuard);
            total += paths;
          });
        });
    total.addTo(result.stats);
    return result;
  });
}

}  // namespace rise
