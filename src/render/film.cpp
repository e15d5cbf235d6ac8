#include "render/film.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rise {
namespace {

constexpr float kGaussianSigma = 0.5f;
// Rows of the image a worker takes at a time when the film is added to or
// resolved whole.
constexpr int kRowsPerRange = 16;

// Calls visit(x, y) at every pixel of a width x height image, the workers
// sharing the rows.
template <typename Visit>
void forEachPixel(int width, int height, const Workers& workers, const Visit& visit) {
  workers.forEachRange(height, kRowsPerRange, [&](int, int firstRow, int endRow) {
    for (int y = firstRow; y < endRow; ++y)
      for (int x = 0; x < width; ++x) visit(x, y);
  });
}

float gaussian(float x) { return std::exp(-x * x / (2.0f * kGaussianSigma * kGaussianSigma)); }

float radiusOf(FilterKind kind) {
  switch (kind) {
    case FilterKind::Box:
      return 0.5f;
    case FilterKind::Tent:
      return 1.0f;
    case FilterKind::Gaussian:
      return 3.0f * kGaussianSigma;
  }
  return 0.5f;
}

// A sample a pixel takes, by the step from the pixel to the sample's, and
// its weight there.
struct Neighbour {
  int dx, dy;
  float weight;
};

// The samples a pixel takes when every sample lies at `offset` in its pixel:
// the same weights everywhere, in the raster order in which
// FilmTile::addSample would add them.
std::vector<Neighbour> neighboursTaken(const ReconstructionFilter& filter, const Vec2& offset) {
  std::vector<Neighbour> neighbours;
  const int reach = static_cast<int>(std::ceil(filter.radius()));
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const float weight = filter.weight(Vec2(static_cast<float>(dx), static_cast<float>(dy)) +
                                         (offset - Vec2(0.5f)));
      if (weight != 0.0f) neighbours.push_back({dx, dy, weight});
    }
  return neighbours;
}

}  // namespace

std::vector<PixelRect> makeTiles(int width, int height, int tileSize) {
  std::vector<PixelRect> tiles;
  for (int y = 0; y < height; y += tileSize)
    for (int x = 0; x < width; x += tileSize)
      tiles.push_back({x, y, std::min(x + tileSize, width), std::min(y + tileSize, height)});
  return tiles;
}

ReconstructionFilter::ReconstructionFilter(FilterKind kind)
    : kind_(kind), radius_(radiusOf(kind)) {}

float ReconstructionFilter::weight1D(float offset) const {
  switch (kind_) {
    // Half-open, so that a sample on the border of two pixels counts once.
    case FilterKind::Box:
      return offset >= -0.5f && offset < 0.5f ? 1.0f : 0.0f;
    case FilterKind::Tent:
      return std::max(0.0f, 1.0f - std::abs(offset));
    // Lowered so that it reaches zero at its radius instead of stopping short.
    case FilterKind::Gaussian:
      return std::max(0.0f, gaussian(offset) - gaussian(radius_));
  }
  return 0.0f;
}

float ReconstructionFilter::weight(const Vec2& offset) const {
  return weight1D(offset.x) * weight1D(offset.y);
}

bool ReconstructionFilter::keepsEachSampleInItsPixel(const Vec2& offset) const {
  const std::vector<Neighbour> neighbours = neighboursTaken(*this, offset);
  return neighbours.size() == 1 && neighbours[0].dx == 0 && neighbours[0].dy == 0 &&
         neighbours[0].weight == 1.0f;
}

Film::Film(int width, int height, FilterKind filter)
    : width_(width), height_(height), filter_(filter) {}

void Film::makeSums() {
  if (!weightSum_.empty()) return;
  const auto pixels = static_cast<std::size_t>(width_) * height_;
  if (!kept_) {
    weightedSum_.assign(pixels, Color(0.0f));
    weightSum_.assign(pixels, 0.0f);
    return;
  }
  // Each of the kept images added 1 x its sample and 1 to the weight.
  weightedSum_.assign(kept_->sum.pixels().begin(), kept_->sum.pixels().end());
  weightSum_.assign(pixels, static_cast<float>(kept_->count));
  kept_.reset();
}

int Film::tileMargin() const { return static_cast<int>(std::ceil(filter_.radius() - 0.5f)); }

PixelRect Film::reachOf(const PixelRect& tile) const {
  const int margin = tileMargin();
  return {std::max(0, tile.x0 - margin), std::max(0, tile.y0 - margin),
          std::min(width_, tile.x1 + margin), std::min(height_, tile.y1 + margin)};
}

FilmTile Film::tileFor(const PixelRect& tile) const {
  const PixelRect reach = reachOf(tile);
  return FilmTile(filter_, reach.x0, reach.y0, reach.x1, reach.y1);
}

void Film::merge(const FilmTile& tile) {
  assert(!kept_);
  makeSums();
  const int tileWidth = tile.x1_ - tile.x0_;
  for (int y = tile.y0_; y < tile.y1_; ++y) {
    for (int x = tile.x0_; x < tile.x1_; ++x) {
      const std::size_t from = static_cast<std::size_t>(y - tile.y0_) * tileWidth + (x - tile.x0_);
      const std::size_t to = static_cast<std::size_t>(y) * width_ + x;
      weightedSum_[to] += tile.weightedSum_[from];
      weightSum_[to] += tile.weightSum_[from];
    }
  }
}

void Film::addImage(Image samples, const Vec2& offset, const Workers& workers) {
  assert(samples.width() == width_ && samples.height() == height_);
  if (weightSum_.empty() && filter_.keepsEachSampleInItsPixel(offset)) {
    if (!kept_) {
      kept_ = KeptImages{std::move(samples), 1};
      return;
    }
    forEachPixel(width_, height_, workers,
                 [&](int x, int y) { kept_->sum.at(x, y) += samples.at(x, y); });
    ++kept_->count;
    return;
  }
  makeSums();
  gather(samples, offset, workers);
}

void Film::addMeans(Image means, int samples, const Workers& workers) {
  assert(means.width() == width_ && means.height() == height_ && weightSum_.empty());
  const auto count = static_cast<float>(samples);
  if (!kept_) {
    forEachPixel(width_, height_, workers, [&](int x, int y) { means.at(x, y) *= count; });
    kept_ = KeptImages{std::move(means), samples};
    return;
  }
  forEachPixel(width_, height_, workers,
               [&](int x, int y) { kept_->sum.at(x, y) += count * means.at(x, y); });
  kept_->count += samples;
}

void Film::gather(const Image& samples, const Vec2& offset, const Workers& workers) {
  const std::vector<Neighbour> neighbours = neighboursTaken(filter_, offset);
  forEachPixel(width_, height_, workers, [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
    for (const Neighbour& n : neighbours) {
      const int sx = x + n.dx, sy = y + n.dy;
      if (sx < 0 || sx >= width_ || sy < 0 || sy >= height_) continue;
      weightedSum_[i] += n.weight * samples.at(sx, sy);
      weightSum_[i] += n.weight;
    }
  });
}

Image Film::resolve(const Workers& workers) {
  if (kept_) {
    Image& sum = kept_->sum;
    // Divided rather than multiplied by the reciprocal: the same colours as
    // the weighted sums give.
    const auto count = static_cast<float>(kept_->count);
    if (kept_->count > 1)
      forEachPixel(width_, height_, workers, [&](int x, int y) { sum.at(x, y) /= count; });
    return std::move(sum);
  }
  Image image(width_, height_);
  if (weightSum_.empty()) return image;
  forEachPixel(width_, height_, workers, [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
    if (weightSum_[i] > 0.0f) image.at(x, y) = weightedSum_[i] / weightSum_[i];
  });
  return image;
}

FilmTile::FilmTile(const ReconstructionFilter& filter, int x0, int y0, int x1, int y1)
    : filter_(&filter),
      x0_(x0),
      y0_(y0),
      x1_(x1),
      y1_(y1),
      weightedSum_(static_cast<std::size_t>(x1 - x0) * (y1 - y0), Color(0.0f)),
      weightSum_(static_cast<std::size_t>(x1 - x0) * (y1 - y0), 0.0f) {}

void FilmTile::addSample(const glm::ivec2& pixel, const Vec2& offset, const Color& color) {
  assert(pixel.x >= x0_ && pixel.x < x1_ && pixel.y >= y0_ && pixel.y < y1_);
  const int tileWidth = x1_ - x0_;
  const auto index = [&](int x, int y) {
    return static_cast<std::size_t>(y - y0_) * tileWidth + (x - x0_);
  };
  if (filter_->kind() == FilterKind::Box) {  // the common case: its own pixel, weight 1
    weightedSum_[index(pixel.x, pixel.y)] += color;
    weightSum_[index(pixel.x, pixel.y)] += 1.0f;
    return;
  }
  // Every pixel whose centre lies within the filter's radius of the sample.
  const int reach = static_cast<int>(std::ceil(filter_->radius()));
  for (int y = std::max(y0_, pixel.y - reach); y <= std::min(y1_ - 1, pixel.y + reach); ++y) {
    for (int x = std::max(x0_, pixel.x - reach); x <= std::min(x1_ - 1, pixel.x + reach); ++x) {
      const Vec2 fromCentre =
          Vec2(static_cast<float>(pixel.x - x), static_cast<float>(pixel.y - y)) +
          (offset - Vec2(0.5f));
      const float weight = filter_->weight(fromCentre);
      if (weight == 0.0f) continue;
      weightedSum_[index(x, y)] += weight * color;
      weightSum_[index(x, y)] += weight;
    }
  }
}

void FilmTile::resolveInto(Image& image, const PixelRect& area) const {
  const int tileWidth = x1_ - x0_;
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y - y0_) * tileWidth + (x - x0_);
      image.at(x, y) = weightSum_[i] > 0.0f ? weightedSum_[i] / weightSum_[i] : Color(0.0f);
    }
  }
}

}  // namespace rise
