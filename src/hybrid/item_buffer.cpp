#include "hybrid/item_buffer.hpp"

#include <utility>

#include "raster/scanline.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace rise {

constexpr int kRowsPerRange = 16;

// The sweep reports its scanlines to a recorder of its own, so that each can
// be told as the item buffer's: the scanline's colours are not the image's
// yet, which the second pass settles. The faces the sweep finds are the
// projection's; each is then told by its number in the scene, so that the
// projection need not be kept: a group of passes holds an item buffer each.
ItemBuffer::ItemBuffer(const Scene& scene, const TessellatedScene& tessellated,
                       const ScreenGeometry& screen, int width, int height, const Workers& workers,
                       StepRecorder* steps, Stats& stats)
    : scene_(scene),
      tessellated_(tessellated),
      sweepSteps_(steps ? std::make_unique<StepRecorder>(steps->budget()) : nullptr),
      faces_(width, height, sweepSteps_.get()) {
  addProjectionStats(stats, screen);
  sweepScanlines(screen, workers, faces_, stats);
  workers.forEachRange(height, kRowsPerRange, [&](int, int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < width; ++x)
        if (const int face = faces_.at(x, y); face >= 0)
          faces_.setVisible(x, y, screen.faces[static_cast<std::size_t>(face)].sceneFace);
  });
  if (steps) recordFilling(sweepSteps_->allSteps(), *steps);
}

Item ItemBuffer::itemOf(int face) const {
  if (face < 0) return {};
  const SceneFace& seen = tessellated_.faces[static_cast<std::size_t>(face)];
  return {seen.shape, seen.primitive};
}

// The sweep's steps are its scanlines, from the top.
void ItemBuffer::recordFilling(const std::vector<Step>& scanlines, StepRecorder& steps) const {
  for (int y = 0; y < static_cast<int>(scanlines.size()); ++y) {
    Step step = scanlines[static_cast<std::size_t>(y)];
    step.text = "item buffer, " + step.text;
    step.settled.clear();
    for (int x = 0; x < faces_.width(); ++x) {
      const int face = faceAt(x, y);
      if (face < 0) continue;
      const Color& color = scene_.materials[tessellated_.faces[face].material].color;
      step.writes.push_back({x, y, color, face});
    }
    steps.record(std::move(step), y);
  }
}

}  // namespace rise
