// Where a visible-surface algorithm puts its answers: for each pixel, the
// face seen there. The frame shades it at once into the image and the
// auxiliary buffers ("depth", "normal", "face"); pixels no face is seen at
// keep the background. The algorithm also charges each pixel the work it
// spent on it, for the "cost" buffer, and reports its steps to the frame's
// recorder when it has one. Algorithms write distinct pixels from distinct
// threads.
#pragma once

#include <cstdint>

#include "raster/surface_shader.hpp"
#include "render/step_recorder.hpp"

namespace rise {

class RasterFrame {
 public:
  RasterFrame(int width, int height, const Color& background, const ScreenGeometry& screen,
              const SurfaceShader& shader, const Workers& workers, StepRecorder* steps);

  int width() const { return result_.image.width(); }
  int height() const { return result_.image.height(); }

  // Screen face `face` is seen at pixel (x, y).
  void setVisible(int x, int y, int face);
  void addCost(int x, int y, float work) { cost_->at(x, y) += Color(work); }

  // Where the algorithm reports its steps, or nullptr when nobody listens.
  StepRecorder* steps() const { return steps_; }
  // Screen face `face` drawn at pixel (x, y) at inverse depth w, for a
  // step's record; `kept` false where it lost a depth test there.
  PixelWrite writeOf(int x, int y, int face, float inverseDepth, bool kept = true) const;
  // The number in the scene of screen face `face`, as the "face" buffer has it.
  int sceneFaceOf(int face) const { return screen_.faces[face].sceneFace; }

  // The number of pixels some face is seen at.
  std::uint64_t coveredPixels() const;

  // The image and its buffers, for the render's result.
  RenderResult takeResult() { return std::move(result_); }

 private:
  const ScreenGeometry& screen_;
  const SurfaceShader& shader_;
  StepRecorder* steps_;
  RenderResult result_;
  Image* depth_;
  Image* normal_;
  Image* face_;
  Image* cost_;
};

// The outline of a polygon on the screen, for a step's record.
StepShape outlineOf(std::span<const Vec3> corners, std::string role);

}  // namespace rise
