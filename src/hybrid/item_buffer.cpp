#include "hybrid/item_buffer.hpp"

#include <utility>

#include "raster/scanline.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace rise {

namespace {

// Where the sweep writes: each face it finds, a face of the projection, is
// kept by its number in the scene, so that the projection need not be kept:
// a group of passes holds an item buffer each.
class SceneFaces final : public VisibleFaces {
 public:
  SceneFaces(FaceBuffer& faces, const ScreenGeometry& screen) : faces_(faces), screen_(screen) {}

  int width() const override { return faces_.width(); }
  int height() const override { return faces_.height(); }
  void setVisible(int x, int y, int face) override {
    faces_.setVisible(x, y,
                      face < 0 ? -1 : screen_.faces[static_cast<std::size_t>(face)].sceneFace);
  }
  void addCost(int x, int y, float work) override { faces_.addCost(x, y, work); }
  bool keepsCost() const override { return faces_.keepsCost(); }
  StepRecorder* steps() const override { return faces_.steps(); }

 private:
  FaceBuffer& faces_;
  const ScreenGeometry& screen_;
};

}  // namespace

// The sweep reports its scanlines to a recorder of its own, so that each can
// be told as the item buffer's: the scanline's colours are not the image's
// yet, which the second pass settles.
ItemBuffer::ItemBuffer(const Scene& scene, const TessellatedScene& tessellated,
                       const ScreenGeometry& screen, int width, int height, const Workers& workers,
                       StepRecorder* steps, Stats& stats)
    : scene_(scene),
      tessellated_(tessellated),
      sweepSteps_(steps ? std::make_unique<StepRecorder>(steps->budget()) : nullptr),
      faces_(width, height, sweepSteps_.get()) {
  addProjectionStats(stats, screen);
  SceneFaces sceneFaces(faces_, screen);
  sweepScanlines(screen, workers, sceneFaces, stats);
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
