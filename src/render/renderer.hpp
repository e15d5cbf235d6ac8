#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.hpp"
#include "core/parallel.hpp"
#include "core/stats.hpp"
#include "render/render_settings.hpp"
#include "render/step_recorder.hpp"
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

  // The buffer of that name, or nullptr where the render made none (the
  // settings did not want it).
  Image* buffer(std::string_view name) {
    const auto found = buffers.find(name);
    return found == buffers.end() ? nullptr : &found->second;
  }
};

// Cuts the image and the auxiliary buffers of its size of a whole-image
// result to `settings`'s region, for the algorithms that render more than it.
void cropToRegion(RenderResult& result, const RenderSettings& settings);

// Watches a render from outside: progress for a bar; cancellation, and the
// image as it is made, for the studio; and the algorithm's steps for whoever
// wants to see them. The render calls it from its worker threads, one call at
// a time but for onPixelsDone.
class RenderObserver : public Progress {
 public:
  // Where the algorithm reports its steps, or nullptr when nobody listens.
  virtual StepRecorder* stepRecorder() { return nullptr; }
  // The pixels of `region` are final in `image` (linear colours, the size of
  // the render's image), so that a front end may show them before the render
  // ends. Called by the task that finished them while others may be writing
  // elsewhere in `image`: read only the region, and only during the call.
  virtual void onPixelsDone(const PixelRect& /*region*/, const Image& /*image*/) {}
};

// The two families of algorithms: those that project polygons and find the
// one visible at each pixel (raster/), and those that trace rays (ray/); and
// the algorithms that join them (hybrid/).
enum class Family { VisibleSurface, RayTracing, Hybrid, Radiosity };

// The settings of RenderSettings that only some algorithms read.
enum class Option {
  Shading,
  Culling,
  Tessellation,
  PlaneSize,
  Shadows,
  Transparency,
  Accel,
  MaxDepth,
  LightSampling,  // and the roulette
  Progression,    // the time limit and the noise target
  Radiosity       // the patches, the residual, the solver, the form factors, the display
};
inline constexpr Option kAllOptions[] = {
    Option::Shading,       Option::Culling,      Option::Tessellation, Option::PlaneSize,
    Option::Shadows,       Option::Transparency, Option::Accel,        Option::MaxDepth,
    Option::LightSampling, Option::Progression,  Option::Radiosity};

// What an algorithm shows of light beyond the Phong model at each surface.
enum class Effect {
  Shadows,
  Reflection,
  Refraction,
  DepthOfField,
  MotionBlur,
  SoftShadows,
  Gloss,
  Transparency,   // transparent surfaces blended over what is behind them, without refraction
  IndirectLight,  // light that other surfaces reflect: colour bleeding, caustics
};

// What a render shows a student of its workings besides its image, when
// asked: its steps in its own words (`rise explain`, the studio's step
// player), and the tree of rays behind a pixel (`rise inspect`, a click in the
// studio's image).
enum class Look { Steps, RayTrees };

// How the statistics of a render cut into tiles (`--tile`, rise-mpi) make
// those of the whole image: summed, where each tile counts only its own
// pixels' work; or any one tile's, where each tile renders the whole image
// and keeps its part (the visible-surface algorithms draw every polygon at
// once).
enum class TileStatistics { Summed, WholeImage };

std::string_view toString(Family family);
std::string_view toString(Option option);  // as on the command line: "shading"
// Every command-line flag of the option, without the dashes: "shadows",
// "shadow-map-size", ...; the first is its toString.
std::span<const std::string_view> flagsOf(Option option);
std::string_view toString(Effect effect);  // in words: "depth of field"
std::string_view toString(Look look);      // in words: "ray trees"

// What an algorithm is and offers, for the command line's help, `rise
// algorithms`, the compare page, the studio and the tests: they read this
// instead of lists of their own.
struct AlgorithmDescription {
  std::string_view name;      // as typed after -a: "ray-tracing"
  std::string_view summary;   // what it does, in one line
  std::string_view citation;  // the paper it follows
  Family family;
  std::vector<std::string_view> buffers;  // the auxiliary buffers it writes: "depth", ...
  std::vector<Option> options;            // the settings it reads beyond the image's
  std::vector<Effect> effects;
  // The algorithm whose image this one renders by other means, or "": `rise
  // compare` counts the pixels where the two differ and the intersection
  // tests this one spared.
  std::string_view sameImageAs = {};
  // How it draws shadows when --shadows asks (ShadowMethod::None, no
  // shadows, goes without saying); empty for an algorithm that does not read
  // the option.
  std::vector<ShadowMethod> shadowMethods = {};
  std::vector<Look> looks = {};
  TileStatistics tileStatistics = TileStatistics::Summed;

  bool offers(Look look) const;
  bool writes(std::string_view buffer) const;
  bool reads(Option option) const;
  bool draws(ShadowMethod method) const;
};

// What a render needs, worked out from its settings before it starts, for
// the limits (render/render_limits.hpp): the memory it takes at most, and
// the most rays it may trace (0 for an algorithm that traces none).
struct RenderNeeds {
  std::uint64_t bytes = 0;
  double rays = 0.0;
  // Where the memory is not mostly the image's: what takes most of it ("the
  // shadow maps of 4 lights, 8192 x 8192 texels each") and how to take less
  // ("smaller shadow maps (--shadow-map-size)").
  std::string mostOfTheMemory = {};
  std::string toTakeLess = {};
  // Whether a material that both reflects and refracts makes its rays
  // branch in two, as Whitted's do and a path's, one direction a surface, do not.
  bool raysBranch = true;
};

// One image synthesis algorithm. The command line, the studio, the tests and
// the benchmarks all render through this one interface.
class Renderer {
 public:
  virtual ~Renderer() = default;

  virtual const AlgorithmDescription& description() const = 0;
  std::string_view name() const { return description().name; }

  virtual RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const = 0;

  virtual RenderResult render(const Scene& scene, const RenderSettings& settings,
                              RenderObserver& observer) const = 0;
};

}  // namespace rise
