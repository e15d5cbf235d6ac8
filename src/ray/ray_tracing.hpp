// Whitted ray tracing (ray_tracing.cpp tells it), and what Cook's distributed
// ray tracing (distributed_ray_tracing.cpp) takes from it: the recursion,
// with the choices a path makes left open, and the adaptive supersampling.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "ray/image_sampler.hpp"
#include "ray/scene_intersector.hpp"
#include "render/renderer.hpp"

namespace rise {

class WhittedRayTracer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

// The choices a path makes at the surfaces it meets, `depth` being the
// surface's place along the path (1: seen from the eye): where on a light a
// shadow ray aims, and where a reflected or refracted ray goes, given the
// ideal direction, the material's roughness and the surface's normal on the
// side the ray left from.
class PathChoices {
 public:
  virtual LightSample aimAt(const Light& light, const Vec3& point, int depth) = 0;
  virtual Vec3 scatter(const Vec3& ideal, float roughness, const Vec3& normal, int depth) = 0;

 protected:
  ~PathChoices() = default;
};

// Whitted's one ray for every choice: the light's centre, the ideal
// direction.
class SingleRayChoices final : public PathChoices {
 public:
  LightSample aimAt(const Light& light, const Vec3& point, int depth) override;
  Vec3 scatter(const Vec3& ideal, float, const Vec3&, int) override { return ideal; }
};

// What the recursion needs besides the ray: the scene, the structure that
// finds what rays hit, and the longest path (the primary ray counting 1).
struct TracingContext {
  const Scene& scene;
  const SceneIntersector& intersector;
  int maxDepth;
};

// Whitted's recursive Intersect and Shade, from a ray that leaves the eye:
// the colour seen along it, and what it hit; every ray recorded in `tree`
// when there is one.
SampleResult tracePrimary(const TracingContext& context, const Ray& ray, PathChoices& choices,
                          TraceCounters& counters, RayTree* tree = nullptr);

// The same once the primary ray's nearest hit is known (nullptr: it hits
// nothing), found by other means than the ray's search (the hybrid
// algorithm's item buffer): Shade, and the rays it spawns. The primary ray is
// not counted.
SampleResult shadeFirstHit(const TracingContext& context, const Ray& ray, const Hit* hit,
                           PathChoices& choices, TraceCounters& counters, RayTree* tree = nullptr);

// The surface at a hit as the shading sees it: the normal turned towards the
// side the ray came from, and whether the ray is entering the solid.
struct ShadingFrame {
  SurfacePoint surface;
  Vec3 normal{0.0f};         // the geometric normal, unit, on the ray's side of the surface
  Vec3 shadingNormal{0.0f};  // the smooth normal for shading, on the same side
  Vec3 toViewer{0.0f};       // unit, back along the ray
  float time = 0.0f;         // the ray's instant, which the rays it spawns keep
  bool entering = false;
};

// A shadow ray that Shade sends towards a light, and what the light's Phong
// terms add to the point where the light arrives unfiltered.
struct LitShadowRay {
  Ray ray;
  float distance = 0.0f;  // to the light, along the ray
  Color lit{0.0f};
  int light = 0;  // the light's place among the scene's
};

// Shade at a primary ray's first hit, cut in two where its shadow rays are
// traced: shading many first hits, a caller may trace all their shadow rays
// between the two halves, together (first_hit_batch.hpp). The two halves
// give shadeFirstHit's colour, to the bit, and count the same rays.
class FirstHitShading {
 public:
  // The first half: the point, its ambient term, and the shadow rays it
  // needs, added to `shadowRays` (the primary ray is not counted).
  FirstHitShading(const TracingContext& context, const Ray& ray, const Hit& hit,
                  PathChoices& choices, TraceCounters& counters,
                  std::vector<LitShadowRay>& shadowRays);

  // The second half, given what each shadow ray let through (`visible`, in
  // the order of `shadowRays`): the lights' terms, then the reflected and
  // refracted rays.
  SampleResult finish(const TracingContext& context, PathChoices& choices, TraceCounters& counters,
                      const std::vector<LitShadowRay>& shadowRays,
                      const std::vector<Color>& visible) const;

  // Its own shadow rays' places in the list the first half added them to:
  // [firstShadowRay(), endOfShadowRays()).
  std::size_t firstShadowRay() const { return firstShadowRay_; }
  std::size_t endOfShadowRays() const { return endOfShadowRays_; }

 private:
  ShadingFrame frame_;
  const Material* material_;
  Color ambient_;
  SampleResult seen_;
  std::size_t firstShadowRay_, endOfShadowRays_;
};

// Traces the sample at a raster position ((i + 0.5, j + 0.5) is pixel (i,
// j)'s centre), recording its rays in `tree` unless that is null.
using TraceAt = std::function<SampleResult(const Vec2& raster, Rng& rng, TraceCounters& counters,
                                           RayTree* tree)>;

// Whitted's adaptive supersampling of every pixel of the tile.
void sampleAdaptively(TileTrace& tile, const RenderSettings& settings, const TraceAt& traceAt);

}  // namespace rise
