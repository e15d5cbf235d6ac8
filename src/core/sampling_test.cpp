#include "core/sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace rise {
namespace {

TEST(Rng, UniformStaysInTheUnitInterval) {
  Rng rng(42);
  double sum = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const float u = rng.uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
  }
  EXPECT_NEAR(sum / 100000.0, 0.5, 0.005);
}

TEST(Rng, TheSameSeedGivesTheSameSequence) {
  Rng a(7), b(7), c(8);
  bool allSame = true;
  for (int i = 0; i < 16; ++i) {
    const std::uint32_t bits = a.nextBits();
    EXPECT_EQ(bits, b.nextBits());
    allSame &= bits == c.nextBits();
  }
  EXPECT_FALSE(allSame);
}

TEST(PixelSeed, NeighboursGetDifferentSeeds) {
  std::set<std::uint64_t> seeds;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) seeds.insert(pixelSeed(0, x, y));
  EXPECT_EQ(seeds.size(), 64u * 64u);
  EXPECT_NE(pixelSeed(0, 3, 4), pixelSeed(1, 3, 4));
}

TEST(GridShape, IsTheGridClosestToSquare) {
  EXPECT_EQ(gridShape(16).columns, 4);
  EXPECT_EQ(gridShape(16).rows, 4);
  EXPECT_EQ(gridShape(8).columns, 4);
  EXPECT_EQ(gridShape(8).rows, 2);
  EXPECT_EQ(gridShape(7).columns, 7);
  EXPECT_EQ(gridShape(7).rows, 1);
  EXPECT_EQ(gridShape(1).columns, 1);
}

TEST(SamplePositions, RegularTakesTheCellCentres) {
  Rng rng(1);
  std::vector<Vec2> positions;
  samplePositions(SamplePattern::Regular, 4, rng, positions);
  ASSERT_EQ(positions.size(), 4u);
  EXPECT_EQ(positions[0], Vec2(0.25f, 0.25f));
  EXPECT_EQ(positions[1], Vec2(0.75f, 0.25f));
  EXPECT_EQ(positions[2], Vec2(0.25f, 0.75f));
  EXPECT_EQ(positions[3], Vec2(0.75f, 0.75f));
}

TEST(SamplePositions, JitteredPutsOneSampleInEachCell) {
  Rng rng(2);
  std::vector<Vec2> positions;
  samplePositions(SamplePattern::Jittered, 16, rng, positions);
  std::set<int> cells;
  for (const Vec2& p : positions) {
    ASSERT_GE(p.x, 0.0f);
    ASSERT_LT(p.x, 1.0f);
    cells.insert(static_cast<int>(p.x * 4) + 4 * static_cast<int>(p.y * 4));
  }
  EXPECT_EQ(cells.size(), 16u);
}

TEST(SamplePositions, NoneIsThePixelCentre) {
  Rng rng(3);
  std::vector<Vec2> positions;
  samplePositions(SamplePattern::None, 1, rng, positions);
  ASSERT_EQ(positions.size(), 1u);
  EXPECT_EQ(positions[0], Vec2(0.5f));
}

TEST(JitteredValues, OnePerIntervalAndNeverOne) {
  Rng rng(4);
  std::vector<float> values;
  jitteredValues(1000, rng, values);
  for (int i = 0; i < 1000; ++i) {
    EXPECT_GE(values[i], i / 1000.0f - 1e-6f);
    EXPECT_LT(values[i], 1.0f);
  }
}

TEST(Shuffle, KeepsEveryItem) {
  Rng rng(5);
  std::vector<int> items{0, 1, 2, 3, 4, 5, 6, 7};
  shuffle(items, rng);
  EXPECT_EQ(std::set<int>(items.begin(), items.end()).size(), 8u);
  EXPECT_NE(items, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(ChooseSampling, ACountAloneMeansJittered) {
  const PixelSampling sampling = chooseSampling({}, 16, std::nullopt);
  EXPECT_EQ(sampling.samples, 16);
  EXPECT_EQ(sampling.pattern, SamplePattern::Jittered);
}

TEST(ChooseSampling, APatternAloneTakesTheReportsSixteenSamples) {
  EXPECT_EQ(chooseSampling({}, std::nullopt, SamplePattern::Random).samples, 16);
  PixelSampling nine;
  nine.samples = 9;
  nine.pattern = SamplePattern::Jittered;
  EXPECT_EQ(chooseSampling(nine, std::nullopt, SamplePattern::Regular).samples, 9);
  EXPECT_EQ(chooseSampling(nine, std::nullopt, SamplePattern::None).samples, 1);
}

TEST(SamplingProblem, NamesWhatCannotBeRendered) {
  PixelSampling sampling;
  EXPECT_EQ(samplingProblem(sampling), "");
  sampling.samples = 4;
  EXPECT_EQ(samplingProblem(sampling),
            "4 samples with the pattern 'none', which takes one sample at the pixel's centre; "
            "expected a pattern to place them: regular, jittered, random or adaptive");
  sampling.pattern = SamplePattern::Adaptive;
  sampling.samples = 8;
  EXPECT_EQ(samplingProblem(sampling),
            "8 samples with the adaptive pattern; expected 1, 4, 16, 64 or 256, as each level of "
            "refinement splits a square into four");
  sampling.samples = 16;
  sampling.filter = FilterKind::Tent;
  EXPECT_EQ(samplingProblem(sampling),
            "the tent filter with the adaptive pattern, which averages its own squares; expected "
            "the box filter, or another pattern");
}

}  // namespace
}  // namespace rise
