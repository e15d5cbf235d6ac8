#include "hybrid/item_buffer.hpp"

#include <utility>

#include "raster/scanline.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace rise {

// The sweep reports its scanlines to a recorder of its own, so that each can
// be told as the item buffer's: the scanline's colours are not the image's
// yet, which the second pass settles.
ItemBuffer::ItemBuffer(const Scene& scene, const TessellatedScene& tessellated,
                       ScreenGeometry screen, int width, int height, const Workers& workers,
                       StepRecorder* steps, Stats& stats)
    : scene_(scene),
      tessellated_(tessellated),
      screen_(std::move(screen)),
      sweepSteps_(steps ? std::make_unique<StepRecorder>(steps->budget()) : nullptr),
      faces_(width, height, sweepSteps_.get()) {
  addProjectionStats(stats, screen_);
  sweepScanlines(screen_, workers, faces_, stats);
  if (steps) recordFilling(sweepSteps_->allSteps(), *steps);
}

Item ItemBuffer::itemOf(int face) const {
  if (face < 0) return {};
  const SceneFace& seen = tessellated_.faces[screen_.faces[face].sceneFace];
  return {seen.shape, seen.primitive};
}

int ItemBuffer::sceneFaceAt(int x, int y) const {
  const int face = faces_.at(x, y);
  return face < 0 ? -1 : screen_.faces[face].sceneFace;
}

// The sweep's steps are its scanlines, from the top.
void ItemBuffer::recordFilling(const std::vector<Step>& scanlines, StepRecorder& steps) const {
  for (int y = 0; y < static_cast<int>(scanlines.size()); ++y) {
    Step step = scanlines[static_cast<std::size_t>(y)];
    step.text = "item buffer, " + step.text;
    step.settled.clear();
    for (int x = 0; x < faces_.width(); ++x) {
      const int face = sceneFaceAt(x, y);
      if (face < 0) continue;
      const Color& color = scene_.materials[tessellated_.faces[face].material].color;
      step.writes.push_back({x, y, color, face});
    }
    steps.record(std::move(step), y);
  }
}

}  // namespace rise
