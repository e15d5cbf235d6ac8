// What every ray tracer shares below its algorithm: the description of the
// family, what a render needs, the context every traced ray reads, and the
// render's opening: the structure that finds what rays hit built for the
// scene, the image's tiles traced on the workers, each pixel's samples laid
// out by one sampler (core/sampler.hpp) or refined adaptively. A ray tracer
// is then its own way of tracing one sample: see ray_tracing.cpp (Whitted),
// distributed_ray_tracing.cpp (Cook), and the hybrid (hybrid/hybrid.cpp),
// which opens as they do and finds its first hits its own way.
#pragma once

#include <functional>
#include <string_view>
#include <vector>

#include "core/sampler.hpp"
#include "ray/image_sampler.hpp"
#include "ray/scene_intersector.hpp"
#include "render/renderer.hpp"
#include "scene/camera.hpp"

namespace rise {

// The description of a ray tracer: what the family shares (its buffers, the
// settings it reads, its steps and ray trees) with the algorithm's own name,
// summary, citation and effects.
AlgorithmDescription rayTracingAlgorithm(std::string_view name, std::string_view summary,
                                         std::string_view citation, std::vector<Effect> effects);

// A ray tracer whose samples each become Whitted's recursion: a path, or a
// tree of them where a material both reflects and refracts.
class RayTracer : public Renderer {
 public:
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
};

// What every ray of a render needs besides itself: the scene, the structure
// that finds what rays hit, the longest path (the primary ray counting 1),
// and the view through which the primary rays leave the eye.
struct TracingContext {
  const Scene& scene;
  const SceneIntersector& intersector;
  int maxDepth;
  ViewFrame view;
};

// The opening of every ray tracer's render: the scene's structure built (on
// the render's threads, with the chosen --accel), the context made, the
// render done by `render`, and what the structure tells of its building added
// to the statistics it returns.
RenderResult renderWithRays(const Scene& scene, const RenderSettings& settings,
                            const std::function<RenderResult(const TracingContext&)>& render);

// A ray tracer's render, tile by tile on the workers (traceImage), each tile
// traced by `traceTile`.
using TileTracer = std::function<void(const TracingContext&, TileTrace&)>;
RenderResult traceTiles(const Scene& scene, const RenderSettings& settings,
                        RenderObserver& observer, const TileTracer& traceTile);

// Traces one sample whose ray passes the raster position `raster` ((i +
// 0.5, j + 0.5) is pixel (i, j)'s centre), taking its other dimensions from
// `values`, and recording its rays in `tree` unless that is null.
using TraceSample = std::function<SampleResult(const Vec2& raster, SampleValues& values,
                                               TraceCounters& counters, RayTree* tree)>;

// Every pixel of the tile, sample by sample: its samples laid out by the
// render's pattern, each with the dimensions of `layout`, or, with the
// adaptive pattern, refined as Whitted's adaptive supersampling refines them
// (adaptive_supersampling.hpp).
void traceEachSample(TileTrace& tile, const RenderSettings& settings, SampleLayout layout,
                     const TraceSample& trace);

}  // namespace rise
