// The heart of both ray tracers: Whitted's recursive Intersect and Shade (T.
// Whitted, "An improved illumination model for shaded display", CACM 23(6),
// 1980), as in the original RISE report's pseudo-code.
//
// A ray finds the nearest surface. There the Phong model sums the ambient
// light and each light that a shadow ray reaches (an opaque shape blocks it,
// a transparent one filters it). Then two new rays carry on recursively: the
// mirror reflection, weighted by the material's `reflection`, and the ray
// refracted by Snell's law, weighted by its `transmission` and tinted by its
// colour (past the critical angle, total internal reflection sends it along
// the mirror direction instead). Rays that hit nothing take the background
// colour; recursion stops at the maximum depth.
//
// Every choice a path makes on the way, where on an area light its shadow
// rays aim and how far a rough surface spreads its reflected and refracted
// rays, comes from a PathSampler. Whitted's ray tracer answers "the centre"
// every time: one ray, one answer. Cook's distributed ray tracer answers with
// samples spread over those choices, and averages.
#pragma once

#include "core/random.hpp"
#include "ray/image_sampler.hpp"
#include "ray/scene_intersector.hpp"
#include "ray/trace_counters.hpp"

namespace rise {

// The sample values a path draws at the surfaces it meets, each in the unit
// square; `depth` is the surface's place along the path (1: seen from the
// eye).
class PathSampler {
 public:
  virtual ~PathSampler() = default;
  virtual Vec2 lightSample(int depth) = 0;  // where on an area light a shadow ray aims
  virtual Vec2 glossSample(int depth) = 0;  // where in a rough surface's lobe a ray goes
};

// Always the centre: area lights act as points at their centres, rough
// surfaces as perfect mirrors and clear glass.
class CentredPathSampler final : public PathSampler {
 public:
  Vec2 lightSample(int) override { return Vec2(0.5f); }
  Vec2 glossSample(int) override { return Vec2(0.5f); }
};

struct ShadingFrame;  // a hit as the shading sees it

class RecursiveTracer {
 public:
  RecursiveTracer(const Scene& scene, const SceneIntersector& intersector, int maxDepth)
      : scene_(scene), intersector_(intersector), maxDepth_(maxDepth) {}

  // The colour seen along a ray from the eye, and what it hit.
  SampleResult tracePrimary(const Ray& ray, PathSampler& paths, TraceCounters& counters) const;

 private:
  Color trace(const Ray& ray, int depth, PathSampler& paths, TraceCounters& counters) const;
  Color shade(const ShadingFrame& frame, const Material& material, int depth, PathSampler& paths,
              TraceCounters& counters) const;
  Color directLight(const ShadingFrame& frame, const Material& material,
                    const SurfaceColors& colors, int depth, PathSampler& paths,
                    TraceCounters& counters) const;
  Color reflected(const ShadingFrame& frame, const Material& material, int depth,
                  PathSampler& paths, TraceCounters& counters) const;
  Color refracted(const ShadingFrame& frame, const Material& material, int depth,
                  PathSampler& paths, TraceCounters& counters) const;

  const Scene& scene_;
  const SceneIntersector& intersector_;
  int maxDepth_;
};

}  // namespace rise
