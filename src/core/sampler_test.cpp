#include "core/sampler.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace rise {
namespace {

constexpr SampleLayout kLayout{.squares = 2, .intervals = 1};

PixelSampling jittered(int samples) { return {samples, SamplePattern::Jittered, FilterKind::Box}; }

// Each dimension of a pixel's 16 samples has one value in each of its 16
// strata: 4 x 4 cells of the square, sixteenths of the interval.
TEST(Sampler, StratifiesEveryDimensionOnItsOwn) {
  Sampler sampler(kLayout);
  Rng rng(3);
  const std::vector<Vec2> offsets = sampler.startPixel(jittered(16), rng);
  std::set<int> pixelCells, firstCells, secondCells, intervals;
  const auto cell = [](const Vec2& value) {
    return static_cast<int>(value.y * 4) * 4 + static_cast<int>(value.x * 4);
  };
  for (int i = 0; i < 16; ++i) {
    pixelCells.insert(cell(offsets[static_cast<std::size_t>(i)]));
    SampleValues values = sampler.valuesOf(i, rng);
    firstCells.insert(cell(values.next2D()));
    intervals.insert(static_cast<int>(values.next1D() * 16));
    secondCells.insert(cell(values.next2D()));
  }
  EXPECT_EQ(pixelCells.size(), 16u);
  EXPECT_EQ(firstCells.size(), 16u);
  EXPECT_EQ(secondCells.size(), 16u);
  EXPECT_EQ(intervals.size(), 16u);
}

// Shuffled apart: over many pixels, the sample in the pixel's top-left
// quarter is in the first square's top-left quarter a quarter of the time,
// not always, as it would be had the dimensions been stratified alike.
TEST(Sampler, ShufflesTheDimensionsApart) {
  Sampler sampler(kLayout);
  int together = 0, inTopLeft = 0;
  for (int pixel = 0; pixel < 2000; ++pixel) {
    Rng rng(static_cast<std::uint64_t>(pixel));
    const std::vector<Vec2>& offsets = sampler.startPixel(jittered(16), rng);
    for (int i = 0; i < 16; ++i) {
      const Vec2 offset = offsets[static_cast<std::size_t>(i)];
      const Vec2 first = sampler.valuesOf(i, rng).next2D();
      if (offset.x >= 0.5f || offset.y >= 0.5f) continue;
      ++inTopLeft;
      together += first.x < 0.5f && first.y < 0.5f;
    }
  }
  EXPECT_NEAR(static_cast<double>(together) / inTopLeft, 0.25, 0.02);
}

// Beyond the layout, and for a sample taken alone, the values are the
// generator's next ones, in the order asked.
TEST(Sampler, GivesTheGeneratorsValuesBeyondItsLayout) {
  Sampler sampler({.squares = 1, .intervals = 0});
  Rng rng(9);
  sampler.startPixel(jittered(4), rng);
  Rng copy = rng;
  SampleValues values = sampler.valuesOf(2, rng);
  values.next2D();
  const float u = copy.uniform();
  EXPECT_EQ(values.next2D(), Vec2(u, copy.uniform()));
  EXPECT_EQ(values.next1D(), copy.uniform());

  Rng alone(11), expected(11);
  SampleValues random(alone);
  EXPECT_EQ(random.next1D(), expected.uniform());
  const float x = expected.uniform();
  EXPECT_EQ(random.next2D(), Vec2(x, expected.uniform()));
}

// With no dimensions beyond the pixel's, the samples are placed as the
// pattern alone places them, drawing the same numbers.
TEST(Sampler, WithoutDimensionsPlacesAsThePatternDoes) {
  for (const SamplePattern pattern : {SamplePattern::None, SamplePattern::Regular,
                                      SamplePattern::Jittered, SamplePattern::Random}) {
    const int samples = pattern == SamplePattern::None ? 1 : 9;
    Sampler sampler({});
    Rng a(5), b(5);
    std::vector<Vec2> placed;
    samplePositions(pattern, samples, b, placed);
    EXPECT_EQ(sampler.startPixel({samples, pattern, FilterKind::Box}, a), placed);
    EXPECT_EQ(a.nextBits(), b.nextBits());
  }
}

TEST(Sampler, TheRandomPatternDrawsEveryDimensionAtRandom) {
  Sampler sampler(kLayout);
  Rng rng(4);
  sampler.startPixel({16, SamplePattern::Random, FilterKind::Box}, rng);
  std::set<int> intervals;
  for (int i = 0; i < 16; ++i)
    intervals.insert(static_cast<int>(sampler.valuesOf(i, rng).next1D() * 16));
  EXPECT_LT(intervals.size(), 16u);  // a stratified one would fill every sixteenth
}

}  // namespace
}  // namespace rise
