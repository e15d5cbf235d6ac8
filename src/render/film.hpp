#pragma once

#include <optional>
#include <vector>

#include "core/image.hpp"
#include "core/parallel.hpp"
#include "core/sampling.hpp"

namespace rise {

// The image cut into square tiles, row by row: the pieces of the film that
// threads fill apart.
std::vector<PixelRect> makeTiles(int width, int height, int tileSize = 16);

// A reconstruction filter: how much a sample counts towards a pixel, by its
// offset from the pixel's centre, in pixels.
class ReconstructionFilter {
 public:
  explicit ReconstructionFilter(FilterKind kind);

  FilterKind kind() const { return kind_; }
  float radius() const { return radius_; }
  float weight(const Vec2& offset) const;
  // Whether a sample at `offset` from its pixel's top-left corner counts
  // toward that pixel alone, with weight 1 (the box filter): then an image
  // of such samples, one a pixel, is its own reconstruction.
  bool keepsEachSampleInItsPixel(const Vec2& offset) const;

 private:
  float weight1D(float offset) const;

  FilterKind kind_;
  float radius_;
};

class FilmTile;

// The image being reconstructed from samples: each pixel keeps the sum of
// its samples' weighted colours and the sum of their weights. Threads add
// samples to tiles of their own; the tiles are merged in tile order once
// they are all done, so the sums, and the image, do not depend on the
// number of threads. The sums are made only when they are needed: a render
// whose tiles are final (tilesAreFinal) never makes them, nor does one
// image whose filter keeps each sample in its pixel.
class Film {
 public:
  Film(int width, int height, FilterKind filter);

  // Whether each tile resolves its pixels to their final colours
  // (FilmTile::resolveInto): the filter takes no sample from beyond its
  // pixel (the box), so no tile needs another's samples.
  bool tilesAreFinal() const { return tileMargin() == 0; }

  // The pixels that the samples taken in `tile` reach: its own and the
  // filter's margin around them.
  PixelRect reachOf(const PixelRect& tile) const;
  // An empty tile covering reachOf(tile).
  FilmTile tileFor(const PixelRect& tile) const;
  // A film takes tiles or images, not both.
  void merge(const FilmTile& tile);

  // Adds an image of samples, each taken in its pixel at the same `offset`
  // (a pass of the accumulation buffer): the same sums, in the same order,
  // as adding them one by one in raster order, but gathered pixel by pixel,
  // so that the workers share the rows. While every image's filter keeps
  // each of its samples in its pixel (the box), the images are summed into
  // the first, whose pixels then need no weights: each has as many samples
  // as there are images, of weight 1. Alone, the first is its own
  // reconstruction.
  void addImage(Image samples, const Vec2& offset, const Workers& workers);

  // Whether the filter counts a sample taken at `offset` from its pixel's
  // top-left corner towards that pixel alone, with weight 1 (the box).
  bool keepsEachSampleInItsPixel(const Vec2& offset) const {
    return filter_.keepsEachSampleInItsPixel(offset);
  }
  // Adds an image of the means of `samples` samples a pixel, each kept in its
  // pixel by the filter (keepsEachSampleInItsPixel), all added while the
  // film holds no sample the filter took elsewhere: the same sums as adding
  // an image for each sample, but for their rounding, with one image of
  // memory rather than one a sample.
  void addMeans(Image means, int samples, const Workers& workers);

  // The weighted average at every pixel, the workers sharing the rows; black
  // where no sample reached. Called once, at the end: an image kept whole
  // is handed over.
  Image resolve(const Workers& workers);

 private:
  // The images added first, while each of them kept its samples in their
  // pixels: their sum, not yet gathered into the sums.
  struct KeptImages {
    Image sum;
    int count;
  };

  // How many pixels beyond its own a sample reaches.
  int tileMargin() const;
  void makeSums();
  void gather(const Image& samples, const Vec2& offset, const Workers& workers);

  int width_;
  int height_;
  ReconstructionFilter filter_;
  std::optional<KeptImages> kept_;
  std::vector<Color> weightedSum_;  // none until needed
  std::vector<float> weightSum_;
};

class FilmTile {
 public:
  // Adds a sample taken in `pixel` at `offset` from its top-left corner
  // (each coordinate in [0, 1)). Given apart, the two stay exact where their
  // float sum would round into the next pixel.
  void addSample(const glm::ivec2& pixel, const Vec2& offset, const Color& color);

  // Writes into `image`, at the pixels of `area` (inside the tile), the
  // weighted average of the samples this tile holds: the final colours when
  // the filter reaches no neighbour (the box), a close preview otherwise.
  void resolveInto(Image& image, const PixelRect& area) const;

 private:
  friend class Film;
  FilmTile(const ReconstructionFilter& filter, int x0, int y0, int x1, int y1);

  const ReconstructionFilter* filter_;
  int x0_, y0_, x1_, y1_;  // the pixels covered, margin included: [x0, x1) x [y0, y1)
  std::vector<Color> weightedSum_;
  std::vector<float> weightSum_;
};

}  // namespace rise
