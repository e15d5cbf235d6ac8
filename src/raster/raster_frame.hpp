// Where a visible-surface algorithm puts its answers: for each pixel, the
// face seen there. The frame shades it at once into the image and the
// auxiliary buffers ("depth", "normal", "face"); pixels no face is seen at
// keep the background. The algorithm also charges each pixel the work it
// spent on it, for the "cost" buffer, and reports its steps to the frame's
// recorder when it has one (visible_faces.hpp). With shadow volumes, each
// opaque face is shaded with the lights its pixel is in the shadow of, as the
// scanline counted them before it showed the pixel; transparent faces, in
// front of that point, take every light.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "raster/shadow_volumes.hpp"
#include "raster/surface_shader.hpp"
#include "raster/visible_faces.hpp"

namespace rise {

class RasterFrame final : public VisibleFaces {
 public:
  // Of the auxiliary buffers, those the settings want.
  RasterFrame(const RenderSettings& settings, const Color& background, const ScreenGeometry& screen,
              const SurfaceShader& shader, const Workers& workers, StepRecorder* steps,
              ShadowVolumes* shadowVolumes = nullptr);

  int width() const override { return result_.image.width(); }
  int height() const override { return result_.image.height(); }

  // Screen face `face` is seen at pixel (x, y).
  void setVisible(int x, int y, int face) override;
  // Screen face `face`, transparent, is seen at pixel (x, y) over what the
  // pixel shows: its own light, plus what is behind filtered by its
  // transmission times its colour (raster/transparency.hpp).
  void blendVisible(int x, int y, int face);
  bool isTransparent(int face) const { return shader_.isTransparent(face); }
  // The colour of transparent face `face` at (x, y) over `behind`.
  Color blendedOver(int x, int y, int face, const Color& behind) const;
  const Color& background() const { return background_; }
  void addCost(int x, int y, float work) override {
    if (cost_) cost_->at(x, y) += Color(work);
  }
  bool keepsCost() const override { return cost_ != nullptr; }

  StepRecorder* steps() const override { return steps_; }
  // The shadow volumes the algorithm is to count, or nullptr.
  ShadowVolumes* shadowVolumes() const { return shadowVolumes_; }
  // Screen face `face` drawn at pixel (x, y) at inverse depth w, for a
  // step's record; `kept` false where it lost a depth test there.
  PixelWrite writeOf(int x, int y, int face, float inverseDepth, bool kept = true) const;
  // The number in the scene of screen face `face`, as the "face" buffer has it.
  int sceneFaceOf(int face) const { return screen_.faces[face].sceneFace; }

  // The number of pixels some face is seen at.
  std::uint64_t coveredPixels() const;
  // The seconds the threads spent shading, added up, estimated from the
  // pixels timed: one in kShadingTimedEvery, spread over the image so that
  // every kind of surface is timed in proportion to its share of the writes.
  double shadingSecondsEstimate() const;
  static constexpr int kShadingTimedEvery = 31;

  // The image as shaded so far.
  const Image& image() const { return result_.image; }

  // The image and its buffers, for the render's result.
  RenderResult takeResult();

 private:
  // What a transparent face lets through: its transmission times its colour.
  Color filterOf(int face) const;
  ShadedPixel shadeAt(int x, int y, int face) const;
  ShadedPixel shadingOf(int x, int y, int face) const;

  const ScreenGeometry& screen_;
  const SurfaceShader& shader_;
  StepRecorder* steps_;
  ShadowVolumes* shadowVolumes_;
  Color background_;
  RenderResult result_;
  Image* depth_ = nullptr;  // or none, where not wanted
  Image* normal_ = nullptr;
  Image* cost_ = nullptr;
  // The scene face seen at each pixel, or -1: the "face" buffer, where
  // wanted, and the pixels covered.
  std::vector<int> faces_;
  bool wantsFaces_;
  // Of the timed pixels' shading, shared by the threads writing the frame.
  mutable std::atomic<std::int64_t> timedShadingNanoseconds_{0};
  mutable std::atomic<std::int64_t> timedPixels_{0};
  mutable std::atomic<std::int64_t> keptPixels_{0};
};

// The outline of a polygon on the screen, for a step's record.
StepShape outlineOf(std::span<const Vec3> corners, std::string role);

}  // namespace rise
