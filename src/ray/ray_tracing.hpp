// Whitted ray tracing (ray_tracing.cpp tells it), and what Cook's distributed
// ray tracing (distributed_ray_tracing.cpp) takes from it: the recursion,
// with the choices a path makes left open, and the adaptive supersampling.
#pragma once

#include <functional>

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

// Traces the sample at a raster position ((i + 0.5, j + 0.5) is pixel (i,
// j)'s centre), recording its rays in `tree` unless that is null.
using TraceAt = std::function<SampleResult(const Vec2& raster, Rng& rng, TraceCounters& counters,
                                           RayTree* tree)>;

// Whitted's adaptive supersampling of every pixel of the tile.
void sampleAdaptively(TileTrace& tile, const RenderSettings& settings, const TraceAt& traceAt);

}  // namespace rise
