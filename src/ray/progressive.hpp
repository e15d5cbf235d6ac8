// A progressive render: the image refined pass after pass, each pass a few
// samples a pixel with a seed of its own, the passes' images averaged, until
// the samples asked for are taken, the time limit would be passed or the
// noise estimated from the samples falls to its target
// (RenderSettings::progression). A front end watching sees the image so far
// after every tile of every pass. The noise is the root mean square of the
// pixels' standard errors (their samples' variance over their count, in
// luminance) over the image's mean luminance; each pixel's variance of its
// mean is the "variance" buffer.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "render/renderer.hpp"

namespace rise {

inline constexpr int kSamplesPerPass = 4;
// The sums of the passes' images and of the samples' luminances and their
// squares, the image shown so far and the variance.
inline constexpr std::uint64_t kPassBytesPerPixel = 3 * sizeof(Color) + 2 * sizeof(double) + 4;

// The settings of pass `pass`: kSamplesPerPass samples a pixel of the
// progression's (fewer in the last), jittered, with a seed of the pass's own.
RenderSettings passSettings(const RenderSettings& settings, int pass);

// What a pass is told and tells: the observer its render reports to, and
// each sample, for the noise.
class ProgressivePass {
 public:
  virtual RenderObserver& observer() = 0;
  // A sample whose ray passes `raster`, of the colour `color`. Called by the
  // worker tracing the pixel.
  virtual void addSample(const Vec2& raster, const Color& color) = 0;

 protected:
  ~ProgressivePass() = default;
};

using PassRender =
    std::function<RenderResult(const RenderSettings& pass, ProgressivePass& progress)>;

// The passes rendered by `renderPass`, and their image; the statistics of
// the passes summed, with the passes, the noise and the samples a second.
RenderResult renderProgressively(const RenderSettings& settings, RenderObserver& observer,
                                 const PassRender& renderPass);

}  // namespace rise
