#include "render/film.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace rise {
namespace {

TEST(ReconstructionFilter, WeightsByDistanceFromTheCentre) {
  const ReconstructionFilter box(FilterKind::Box);
  EXPECT_EQ(box.weight({0.49f, -0.5f}), 1.0f);
  EXPECT_EQ(box.weight({0.5f, 0.0f}), 0.0f);  // half-open: the border counts for one pixel
  const ReconstructionFilter tent(FilterKind::Tent);
  EXPECT_FLOAT_EQ(tent.weight({0.5f, 0.0f}), 0.5f);
  EXPECT_FLOAT_EQ(tent.weight({0.5f, 0.5f}), 0.25f);
  EXPECT_EQ(tent.weight({1.0f, 0.0f}), 0.0f);
  const ReconstructionFilter gaussian(FilterKind::Gaussian);
  EXPECT_GT(gaussian.weight({0.0f, 0.0f}), gaussian.weight({0.7f, 0.0f}));
  EXPECT_EQ(gaussian.weight({1.5f, 0.0f}), 0.0f);
}

// Merges every tile of a film that received `perPixel` samples of `color` at
// the given offsets in each pixel.
Image filmOf(FilterKind filter, int width, int height, const std::function<Color(int, int)>& color,
             const std::vector<Vec2>& offsets) {
  Film film(width, height, filter);
  for (const PixelRect& tile : makeTiles(width, height, 4)) {
    FilmTile filmTile = film.tileFor(tile);
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x)
        for (const Vec2& offset : offsets) filmTile.addSample({x, y}, offset, color(x, y));
    film.merge(filmTile);
  }
  return film.resolve(Workers(2));
}

TEST(Film, BoxAveragesEachPixelsOwnSamples) {
  const Image image =
      filmOf(FilterKind::Box, 8, 8, [](int x, int) { return Color(static_cast<float>(x)); },
             {{0.25f, 0.25f}, {0.75f, 0.75f}});
  for (int x = 0; x < 8; ++x) EXPECT_FLOAT_EQ(image.at(x, 3).r, static_cast<float>(x));
}

TEST(Film, EveryFilterKeepsAConstantImageConstant) {
  for (FilterKind filter : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian}) {
    const Image image = filmOf(filter, 9, 7, [](int, int) { return Color(0.3f, 0.6f, 0.9f); },
                               {{0.1f, 0.2f}, {0.6f, 0.3f}, {0.4f, 0.9f}});
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 9; ++x) EXPECT_NEAR(image.at(x, y).g, 0.6f, 1e-5f) << toString(filter);
  }
}

// A tent filter blends a pixel with its neighbours across tile borders: an
// edge between 0 and 1 softens, and comes out the same whatever the tiling.
TEST(Film, TentBlendsNeighboursAcrossTiles) {
  const auto step = [](int x, int) { return Color(x < 4 ? 0.0f : 1.0f); };
  const Image image = filmOf(FilterKind::Tent, 8, 8, step, {{0.25f, 0.5f}, {0.75f, 0.5f}});
  EXPECT_FLOAT_EQ(image.at(0, 0).r, 0.0f);
  EXPECT_GT(image.at(3, 0).r, 0.0f);
  EXPECT_LT(image.at(4, 0).r, 1.0f);
  EXPECT_FLOAT_EQ(image.at(3, 0).r + image.at(4, 0).r, 1.0f);  // symmetric about the edge
}

// A pass of the accumulation buffer added whole gives the image that its
// samples added one by one, in raster order, give: bit for bit, with every
// filter, at offsets on and off the pixels' borders, on any number of threads.
// The tent keeps the first two passes' samples, at the pixels' centres, in
// their pixels, and the later ones not.
TEST(Film, AnImageAddedWholeEqualsItsSamplesAddedOneByOne) {
  const int width = 13, height = 9;
  const auto color = [](int x, int y, int pass) {
    return Color(0.1f * static_cast<float>(x % 5), 0.37f * static_cast<float>(y % 3),
                 0.05f * static_cast<float>(pass + x * y % 7));
  };
  const std::vector<Vec2> offsets = {
      {0.5f, 0.5f}, {0.5f, 0.5f}, {0.0f, 0.999f}, {0.13f, 0.71f}, {0.9f, 0.2f}};
  for (FilterKind filter : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian}) {
    Film oneByOne(width, height, filter);
    FilmTile whole = oneByOne.tileFor({0, 0, width, height});
    for (int pass = 0; pass < static_cast<int>(offsets.size()); ++pass)
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) whole.addSample({x, y}, offsets[pass], color(x, y, pass));
    oneByOne.merge(whole);
    const Image expected = oneByOne.resolve(Workers(1));
    for (int threads : {1, 3}) {
      Film byImages(width, height, filter);
      for (int pass = 0; pass < static_cast<int>(offsets.size()); ++pass) {
        Image samples(width, height);
        for (int y = 0; y < height; ++y)
          for (int x = 0; x < width; ++x) samples.at(x, y) = color(x, y, pass);
        byImages.addImage(samples, offsets[pass], Workers(threads));
      }
      EXPECT_EQ(byImages.resolve(Workers(threads)).pixels(), expected.pixels())
          << toString(filter) << ", " << threads << " threads";
    }
  }
}

// Samples kept in their pixels (the box filter) may be added as the means
// of several a pixel, one image for many: the same image as adding each
// sample's, but for rounding, whatever came before them and on any number
// of threads.
TEST(Film, MeansOfSamplesKeptInTheirPixelsCountAsThatManySamples) {
  const int width = 7, height = 5;
  const auto color = [](int x, int y, int sample) {
    return Color(0.3f * static_cast<float>(x + sample), 1.0f / static_cast<float>(y + sample + 1),
                 0.01f * static_cast<float>(x * y + 1));
  };
  const Vec2 offset(0.25f, 0.75f);
  const auto imageOf = [&](int sample) {
    Image samples(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) samples.at(x, y) = color(x, y, sample);
    return samples;
  };
  const auto meansOf = [&](int first, int count) {
    Image means(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int sample = first; sample < first + count; ++sample)
          means.at(x, y) += color(x, y, sample) / static_cast<float>(count);
    return means;
  };
  Film byImages(width, height, FilterKind::Box);
  for (int sample = 0; sample < 8; ++sample) byImages.addImage(imageOf(sample), offset, Workers(1));
  const Image expected = byImages.resolve(Workers(1));
  for (int threads : {1, 3}) {
    Film byMeans(width, height, FilterKind::Box);
    byMeans.addMeans(meansOf(0, 3), 3, Workers(threads));
    byMeans.addImage(imageOf(3), offset, Workers(threads));
    byMeans.addMeans(meansOf(4, 4), 4, Workers(threads));
    const Image image = byMeans.resolve(Workers(threads));
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int channel = 0; channel < 3; ++channel)
          EXPECT_NEAR(image.at(x, y)[channel], expected.at(x, y)[channel], 1e-6f)
              << x << "," << y << ", " << threads << " threads";
  }
}

// What lets a render skip the film: the box filter's samples stay in their
// pixels, so each tile resolves to the final colours and one image of
// samples, one a pixel, is its own reconstruction, to the bit.
TEST(Film, BoxTilesAndLoneImagesAreTheirOwnReconstruction) {
  const int width = 11, height = 7;
  Image samples(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      samples.at(x, y) = Color(0.1f * static_cast<float>(x), 1.0f / static_cast<float>(y + 3),
                               0.7f * static_cast<float>(x * y % 5) + 0.013f);
  for (const Vec2& offset : {Vec2(0.5f), Vec2(0.0f), Vec2(0.999f, 0.31f)}) {
    for (FilterKind filter : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian}) {
      const bool box = filter == FilterKind::Box;
      // The tent weighs a sample at the pixel's centre 1 there and 0 at
      // its neighbours.
      const bool alone = box || (filter == FilterKind::Tent && offset == Vec2(0.5f));
      EXPECT_EQ(ReconstructionFilter(filter).keepsEachSampleInItsPixel(offset), alone)
          << toString(filter) << " at " << offset.x << ", " << offset.y;
      Film film(width, height, filter);
      EXPECT_EQ(film.tilesAreFinal(), box);
      if (!box) continue;
      FilmTile tile = film.tileFor({0, 0, width, height});
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) tile.addSample({x, y}, offset, samples.at(x, y));
      Image fromTile(width, height);
      tile.resolveInto(fromTile, {0, 0, width, height});
      film.addImage(samples, offset, Workers(2));
      EXPECT_EQ(film.resolve(Workers(2)).pixels(), samples.pixels());
      EXPECT_EQ(fromTile.pixels(), samples.pixels());
    }
  }
}

}  // namespace
}  // namespace rise
