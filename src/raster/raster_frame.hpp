// Where a visible-surface algorithm puts its answers: for each pixel, the
// face seen there. The frame shades it at once into the image and the
// auxiliary buffers ("depth", "normal", "face"); pixels no face is seen at
// keep the background. The algorithm also charges each pixel the work it
// spent on it, for the "cost" buffer (visible_faces.hpp).
#pragma once

#include <cstdint>

#include "raster/surface_shader.hpp"
#include "raster/visible_faces.hpp"

namespace rise {

class RasterFrame final : public VisibleFaces {
 public:
  RasterFrame(int width, int height, const Color& background, const ScreenGeometry& screen,
              const SurfaceShader& shader, const Workers& workers);

  int width() const override { return result_.image.width(); }
  int height() const override { return result_.image.height(); }

  void setVisible(int x, int y, int face) override;
  void addCost(int x, int y, float work) override { cost_->at(x, y) += Color(work); }

  // The number of pixels some face is seen at.
  std::uint64_t coveredPixels() const;

  // The image and its buffers, for the render's result.
  RenderResult takeResult() { return std::move(result_); }

 private:
  const ScreenGeometry& screen_;
  const SurfaceShader& shader_;
  RenderResult result_;
  Image* depth_;
  Image* normal_;
  Image* face_;
  Image* cost_;
};

}  // namespace rise
