// Where a visible-surface algorithm tells what it finds: the face seen at each
// pixel, the work it spent there, and the steps it took. A RasterFrame shades each answer at
// once; a FaceBuffer only keeps it, as an item buffer (Weghorst, Hooper and
// Greenberg, "Improved computational methods for ray tracing", ACM TOG 3(1),
// 1984) for an algorithm that shades by other means. Algorithms write
// distinct pixels from distinct threads.
#pragma once

#include <vector>

#include "render/step_recorder.hpp"

namespace rise {

class VisibleFaces {
 public:
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Screen face `face` (into ScreenGeometry::faces) is seen at pixel (x, y).
  virtual void setVisible(int x, int y, int face) = 0;
  // The algorithm spent `work` more on pixel (x, y), for the "cost" buffer.
  virtual void addCost(int x, int y, float work) = 0;
  // Whether that work is kept: an algorithm that adds it up before telling
  // it need not where nobody keeps it.
  virtual bool keepsCost() const = 0;
  // Where the algorithm reports its steps, or nullptr when nobody listens.
  virtual StepRecorder* steps() const = 0;

 protected:
  ~VisibleFaces() = default;
};

// The screen face seen at each pixel, -1 where none is; the work is not kept,
// the steps go to `steps` when it is not nullptr.
class FaceBuffer final : public VisibleFaces {
 public:
  FaceBuffer(int width, int height, StepRecorder* steps = nullptr)
      : width_(width),
        height_(height),
        steps_(steps),
        faces_(static_cast<std::size_t>(width) * height, -1) {}

  int width() const override { return width_; }
  int height() const override { return height_; }
  void setVisible(int x, int y, int face) override { faces_[index(x, y)] = face; }
  void addCost(int, int, float) override {}
  bool keepsCost() const override { return false; }
  StepRecorder* steps() const override { return steps_; }

  int at(int x, int y) const { return faces_[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

  int width_, height_;
  StepRecorder* steps_;
  std::vector<int> faces_;
};

}  // namespace rise
