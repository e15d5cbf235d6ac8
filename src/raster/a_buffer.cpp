#include "raster/a_buffer.hpp"

#include <algorithm>

#include "raster/bands.hpp"
#include "raster/transparency.hpp"

namespace rise {

ABufferCounters& ABufferCounters::operator+=(const ABufferCounters& other) {
  fragmentsStored += other.fragmentsStored;
  fragmentsCut += other.fragmentsCut;
  mostFragmentsAPixel = std::max(mostFragmentsAPixel, other.mostFragmentsAPixel);
  mostBytes = std::max(mostBytes, other.mostBytes);
  return *this;
}

ABuffer::ABuffer(const PixelRect& band, std::size_t mostFragments)
    : band_(band), first_(static_cast<std::size_t>(band.width()) * band.height(), -1) {
  // Taken whole at once, so that the lists never move and never take more
  // than was worked out.
  fragments_.reserve(mostFragments);
  counters_.mostBytes = first_.size() * sizeof(int);
}

bool ABuffer::add(int x, int y, float inverseDepth, int face, float opaqueDepth) {
  if (inverseDepth <= opaqueDepth) {
    ++counters_.fragmentsCut;
    return false;
  }
  int& first = first_[index(x, y)];
  const Fragment fragment{inverseDepth, face, first};
  if (free_ >= 0) {
    first = free_;
    free_ = fragments_[static_cast<std::size_t>(free_)].next;
    fragments_[static_cast<std::size_t>(first)] = fragment;
  } else {
    first = static_cast<int>(fragments_.size());
    fragments_.push_back(fragment);
    counters_.mostBytes += kBytesAFragment;
  }
  ++counters_.fragmentsStored;
  return true;
}

void ABuffer::cutBehind(int x, int y, float inverseDepth) {
  int* link = &first_[index(x, y)];
  while (*link >= 0) {
    Fragment& fragment = fragments_[static_cast<std::size_t>(*link)];
    if (fragment.inverseDepth > inverseDepth) {
      link = &fragment.next;
      continue;
    }
    const int cut = *link;
    *link = fragment.next;
    fragment.next = free_;
    free_ = cut;
    ++counters_.fragmentsCut;
  }
}

std::uint64_t ABuffer::show(RasterFrame& frame, int x, int y, int opaque) {
  int& first = first_[index(x, y)];
  sorted_.clear();
  for (int at = first; at >= 0; at = fragments_[static_cast<std::size_t>(at)].next)
    sorted_.push_back(fragments_[static_cast<std::size_t>(at)]);
  first = -1;
  // Farthest first; fragments as deep take the order of their faces, not of
  // their coming, so that the image does not depend on the polygons' order.
  std::sort(sorted_.begin(), sorted_.end(), [](const Fragment& a, const Fragment& b) {
    return a.inverseDepth != b.inverseDepth ? a.inverseDepth < b.inverseDepth : a.face < b.face;
  });
  faces_.clear();
  for (const Fragment& fragment : sorted_) faces_.push_back(fragment.face);
  counters_.mostFragmentsAPixel =
      std::max<std::uint64_t>(counters_.mostFragmentsAPixel, faces_.size());
  return showLayers(frame, x, y, opaque, faces_);
}

std::vector<std::size_t> mostFragmentsByBand(const ScreenGeometry& screen,
                                             const RasterFrame& frame) {
  const std::vector<PixelRect> bands = makeBands(frame.width(), frame.height());
  const PixelRect image{0, 0, frame.width(), frame.height()};
  std::vector<std::size_t> most(bands.size(), 0);
  for (const ScreenPolygon& polygon : screen.polygons) {
    if (!frame.isTransparent(polygon.face)) continue;
    const PixelRect bounds = pixelBoundsOf(screen.cornersOf(polygon)).intersection(image);
    if (bounds.isEmpty()) continue;
    for (int band = bounds.y0 / kBandHeight; band <= (bounds.y1 - 1) / kBandHeight; ++band) {
      const PixelRect inBand = bounds.intersection(bands[static_cast<std::size_t>(band)]);
      most[static_cast<std::size_t>(band)] +=
          static_cast<std::size_t>(inBand.width()) * inBand.height();
    }
  }
  return most;
}

}  // namespace rise
