// The first pass of the hybrid algorithm (hybrid.cpp): the item buffer of
// Weghorst, Hooper and Greenberg, filled by the scanline algorithm's sweep
// (scanline.cpp) at the pixel centres where the primary rays pass. It tells,
// for each pixel, the object seen there and, for an object of several
// primitives (a mesh), the one under the polygon.
#pragma once

#include <compare>
#include <memory>

#include "raster/screen_geometry.hpp"
#include "raster/tessellated_scene.hpp"
#include "raster/visible_faces.hpp"
#include "render/renderer.hpp"

namespace rise {

// What the item buffer says a pixel sees. Ordered as the acceleration
// structures break ties between hits at the same distance.
struct Item {
  int shape = -1;  // -1: nothing, the background
  int primitive = 0;

  bool operator==(const Item&) const = default;
  auto operator<=>(const Item&) const = default;
};

class ItemBuffer {
 public:
  // Sweeps the tessellated scene, projected (`screen`), scanline by scanline
  // over a width x height image, adding the projection's and the sweep's
  // counters to `stats`. Each scanline is a step for `steps` (when not
  // null): the scanline's own step, its items drawn in their materials'
  // colours.
  ItemBuffer(const Scene& scene, const TessellatedScene& tessellated, const ScreenGeometry& screen,
             int width, int height, const Workers& workers, StepRecorder* steps, Stats& stats);

  Item itemAt(int x, int y) const { return itemOf(faceAt(x, y)); }
  // The scene's number of the face seen at the pixel, as the "face" buffer
  // has it, -1 for none, and the item it lies on.
  int faceAt(int x, int y) const { return faces_.at(x, y); }
  Item itemOf(int face) const;

 private:
  void recordFilling(const std::vector<Step>& scanlines, StepRecorder& steps) const;

  const Scene& scene_;
  const TessellatedScene& tessellated_;
  std::unique_ptr<StepRecorder> sweepSteps_;  // the sweep's own steps, when recorded
  FaceBuffer faces_;                          // by the scene's face numbers
};

}  // namespace rise
