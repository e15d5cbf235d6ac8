#include "io/byte_encoding.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace rise {
namespace {

class ByteEncoderTest : public testing::TestWithParam<Encoding> {};

// Every 101st float of [0, 1] (ten million of them, every exponent), and
// both sides of every level's start: the table gives the level that the
// power and the rounding give.
TEST_P(ByteEncoderTest, GivesTheComputedLevelOfEveryValue) {
  const Encoding encoding = GetParam();
  const ByteEncoder& toByte = byteEncoder(encoding);
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  int mismatches = 0;
  for (std::uint32_t bits = 0; bits <= one; bits += 101) {
    const float value = std::bit_cast<float>(bits);
    if (toByte(value) != byteFromLinear(value, encoding) && ++mismatches < 10)
      ADD_FAILURE() << value;
  }
  for (int level = 1; level < 256; ++level) {
    const float start = toByte.levelStart(level);
    EXPECT_EQ(byteFromLinear(start, encoding), level);
    EXPECT_EQ(byteFromLinear(std::nextafter(start, 0.0f), encoding), level - 1);
    EXPECT_EQ(toByte(start), level);
    EXPECT_EQ(toByte(std::nextafter(start, 0.0f)), level - 1);
  }
}

TEST_P(ByteEncoderTest, ClampsAndTurnsNanBlack) {
  const ByteEncoder& toByte = byteEncoder(GetParam());
  EXPECT_EQ(toByte(-1.0f), 0);
  EXPECT_EQ(toByte(-0.0f), 0);
  EXPECT_EQ(toByte(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(toByte(1.0f), 255);
  EXPECT_EQ(toByte(7.5f), 255);
  EXPECT_EQ(toByte(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(toByte(-std::numeric_limits<float>::infinity()), 0);
}

INSTANTIATE_TEST_SUITE_P(Encodings, ByteEncoderTest,
                         testing::Values(Encoding::Srgb, Encoding::Linear));

TEST(ByteEncoder, KnownLevels) {
  EXPECT_EQ(byteEncoder(Encoding::Linear)(0.5f), 128);  // 127.5 rounds away from zero
  EXPECT_EQ(byteEncoder(Encoding::Srgb)(0.5f), 188);    // 0.7354 of 255
  EXPECT_EQ(byteEncoder(Encoding::Srgb)(0.001f), 3);    // the linear segment: 3.29
}

}  // namespace
}  // namespace rise
