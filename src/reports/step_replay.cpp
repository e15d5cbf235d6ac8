#include "reports/step_replay.hpp"

#include <algorithm>

namespace rise {

StepReplay::StepReplay(const Color& background, const Image& finalImage)
    : final_(finalImage),
      image_(finalImage.width(), finalImage.height(), background),
      inverseDepth_(static_cast<std::size_t>(finalImage.width()) * finalImage.height(), 0.0f) {}

void StepReplay::apply(const Step& step) {
  apply(step.writesBefore, step.settledBefore);
  apply(step.writes, step.settled);
}

void StepReplay::apply(const std::vector<PixelWrite>& writes,
                       const std::vector<PixelRect>& settled) {
  for (const PixelWrite& write : writes) {
    if (!write.kept) continue;
    image_.at(write.x, write.y) = write.color;
    if (write.inverseDepth <= 0.0f) continue;
    hasDepths_ = true;
    inverseDepth_[static_cast<std::size_t>(write.y) * image_.width() + write.x] =
        write.inverseDepth;
  }
  for (const PixelRect& area : settled)
    for (int y = area.y0; y < area.y1; ++y)
      for (int x = area.x0; x < area.x1; ++x) image_.at(x, y) = final_.at(x, y);
}

// Inverse depths spread from the farthest drawn (dark grey) to the nearest
// (white); 0, the buffer's starting value, infinitely far, stays black.
Image StepReplay::depthImage() const {
  float nearest = 0.0f, farthest = kInfinity;
  for (float w : inverseDepth_) {
    if (w <= 0.0f) continue;
    nearest = std::max(nearest, w);
    farthest = std::min(farthest, w);
  }
  Image depth(image_.width(), image_.height());
  const float range = std::max(nearest - farthest, 1e-30f);
  for (int y = 0; y < depth.height(); ++y) {
    for (int x = 0; x < depth.width(); ++x) {
      const float w = inverseDepth_[static_cast<std::size_t>(y) * depth.width() + x];
      if (w > 0.0f) depth.at(x, y) = Color(0.2f + 0.8f * (w - farthest) / range);
    }
  }
  return depth;
}

}  // namespace rise
