#include "raster/transparency.hpp"

#include <algorithm>
#include <numeric>

namespace rise {

std::vector<int> transparentBackToFront(const ScreenGeometry& screen, const RasterFrame& frame,
                                        std::span<const int> polygons) {
  std::vector<int> transparent;
  std::vector<float> farthest;  // the smallest inverse depth of a corner
  for (int polygon : polygons) {
    if (!frame.isTransparent(screen.polygons[polygon].face)) continue;
    transparent.push_back(polygon);
    float w = kInfinity;
    for (const Vec3& corner : screen.cornersOf(screen.polygons[polygon])) w = std::min(w, corner.z);
    farthest.push_back(w);
  }
  std::vector<int> order(transparent.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return farthest[a] < farthest[b]; });
  std::vector<int> sorted;
  for (int i : order) sorted.push_back(transparent[i]);
  return sorted;
}

PaintedLayers::PaintedLayers(const PixelRect& band)
    : band_(band),
      opaque_(static_cast<std::size_t>(band.width()) * band.height(), -1),
      over_(opaque_.size()) {}

void PaintedLayers::paint(int x, int y, int face, bool transparent) {
  const std::size_t pixel = index(x, y);
  if (transparent) {
    over_[pixel].push_back(face);
    return;
  }
  opaque_[pixel] = face;
  over_[pixel].clear();
}

Color PaintedLayers::shownAt(const RasterFrame& frame, int x, int y) const {
  const std::size_t pixel = index(x, y);
  Color shown =
      opaque_[pixel] >= 0 ? frame.writeOf(x, y, opaque_[pixel], 0.0f).color : frame.background();
  for (int face : over_[pixel]) shown = frame.blendedOver(x, y, face, shown);
  return shown;
}

std::uint64_t PaintedLayers::show(RasterFrame& frame) const {
  std::uint64_t blends = 0;
  for (int y = band_.y0; y < band_.y1; ++y)
    for (int x = band_.x0; x < band_.x1; ++x) {
      const std::size_t pixel = index(x, y);
      blends += showLayers(frame, x, y, opaque_[pixel], over_[pixel]);
    }
  return blends;
}

std::uint64_t showLayers(RasterFrame& frame, int x, int y, int opaque, std::span<const int> over) {
  if (opaque >= 0) frame.setVisible(x, y, opaque);
  for (int face : over) frame.blendVisible(x, y, face);
  return over.size();
}

void TransparentRow::add(int x, float inverseDepth, int face) {
  std::vector<Layer>& layers = layers_[static_cast<std::size_t>(x)];
  const auto place =
      std::upper_bound(layers.begin(), layers.end(), inverseDepth,
                       [](float w, const Layer& layer) { return w < layer.inverseDepth; });
  layers.insert(place, {inverseDepth, face});
  ++held_;
}

std::uint64_t TransparentRow::show(RasterFrame& frame, int x, int y, int opaque,
                                   float opaqueDepth) {
  std::vector<Layer>& layers = layers_[static_cast<std::size_t>(x)];
  inFront_.clear();
  for (const Layer& layer : layers)
    if (layer.inverseDepth > opaqueDepth) inFront_.push_back(layer.face);
  held_ -= layers.size();
  layers.clear();
  return showLayers(frame, x, y, opaque, inFront_);
}

}  // namespace rise
