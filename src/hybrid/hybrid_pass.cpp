#include "hybrid/hybrid_group.hpp"

namespace rise::hybrid {

RenderResult blankResult(const RenderSettings& settings, bool whatWasHit) {
  const auto unfilled = [&] { return Image::unfilled(settings.width, settings.height); };
  RenderResult result;
  if (settings.wantsBuffer("cost")) result.buffers.emplace("cost", unfilled());
  if (whatWasHit)
    for (const char* name : {"depth", "normal", "face"})
      if (settings.wantsBuffer(name)) result.buffers.emplace(name, unfilled());
  return result;
}

// A pixel shaded after its band, to the observer, where it changed the
// image it is shown: the first pass's samples, and those that share them.
void HybridGroup::showShaded(const GroupPass& pass, int x, int y) {
  if (&pass.samples == &passes_.front().samples)
    observer_.onPixelsDone({x, y, x + 1, y + 1}, pass.samples.means);
}

// Each image of samples to the film: shared by all the passes, as the
// means of as many samples; else each pass's at its offset.
void HybridGroup::addSamplesToFilm() {
  for (GroupPass& pass : passes_) {
    if (!pass.clearsSamples) continue;
    SampleImage& samples = pass.samples;
    if (samples.passes > 1)
      film_.addMeans(std::move(samples.means), samples.passes, workers_);
    else
      film_.addImage(std::move(samples.means), pass.pass.pixelOffset, workers_);
  }
}

}  // namespace rise::hybrid
