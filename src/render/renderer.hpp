#pragma once

#include <map>
#include <string>
#include <string_view>

#include "core/image.hpp"
#include "core/stats.hpp"
#include "render/render_settings.hpp"
#include "scene/scene.hpp"

namespace rise {

// What every algorithm returns: the image (linear colours), the auxiliary
// buffers (AOVs) that show what happened at each pixel, and the statistics.
// Buffers hold raw values: "depth" the distance along the primary ray in
// every channel (infinite where nothing was hit), "normal" the unit surface
// normal, "cost" the number of intersection tests made for the pixel (the
// visible-surface algorithms: the work they spent on it, see
// raster/visible_surface_renderer.hpp), "face" the number of the polygon seen
// there (-1 where none is).
struct RenderResult {
  Image image;
  std::map<std::string, Image, std::less<>> buffers;
  Stats stats;
};

// Watches a render from outside: progress for a bar, cancellation for the
// studio. The render calls it from its worker threads, one call at a time.
class RenderObserver {
 public:
  virtual ~RenderObserver() = default;
  virtual void onProgress(double /*fractionDone*/) {}
  virtual bool cancelled() const { return false; }
};

// One image synthesis algorithm. The command line, the studio, the tests and
// the benchmarks all render through this one interface.
class Renderer {
 public:
  virtual ~Renderer() = default;

  virtual std::string_view name() const = 0;      // as typed after -a: "ray-tracing"
  virtual std::string_view summary() const = 0;   // what it does, in one line
  virtual std::string_view citation() const = 0;  // the paper it follows

  virtual RenderResult render(const Scene& scene, const RenderSettings& settings,
                              RenderObserver& observer) const = 0;
};

}  // namespace rise
