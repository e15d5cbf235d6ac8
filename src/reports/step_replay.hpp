// The image as it stood after each recorded step: what the step player shows.
// It starts as the background; each step's pixels take the colours it gave
// them, and the pixels it settled take the render's final colours. Where the
// steps drew at depths (the z-buffer), the depth buffer is rebuilt too.
#pragma once

#include <vector>

#include "core/image.hpp"
#include "render/step_recorder.hpp"

namespace rise {

class StepReplay {
 public:
  StepReplay(const Color& background, const Image& finalImage);

  void apply(const Step& step);

  const Image& image() const { return image_; }
  // Whether any step drew at a depth, and the depth buffer as an image (near
  // white, far black, empty black).
  bool hasDepths() const { return hasDepths_; }
  Image depthImage() const;

 private:
  void apply(const std::vector<PixelWrite>& writes, const std::vector<PixelRect>& settled);

  const Image& final_;
  Image image_;
  std::vector<float> inverseDepth_;
  bool hasDepths_ = false;
};

}  // namespace rise
