#include "io/yaml_reader.hpp"

#include <gtest/gtest.h>

namespace rise {
namespace {

const std::vector<std::string> kSphereKeys{"center", "radius", "material", "transform"};

TEST(SuggestAlternative, NamesTheKeyOneEditAway) {
  EXPECT_EQ(suggestAlternative("radus", kSphereKeys), "did you mean 'radius'?");
  EXPECT_EQ(suggestAlternative("materail", kSphereKeys), "did you mean 'material'?");
}

TEST(SuggestAlternative, IgnoresCase) {
  EXPECT_EQ(suggestAlternative("Center", kSphereKeys), "did you mean 'center'?");
}

TEST(SuggestAlternative, CountsASwapOfNeighbouringLettersAsOneEdit) {
  // "iro" is two substitutions from "ior", too many for a three-letter word.
  EXPECT_EQ(suggestAlternative("iro", {"ior", "ka"}), "did you mean 'ior'?");
}

TEST(SuggestAlternative, ListsTheCandidatesWhenNoneIsClose) {
  EXPECT_EQ(suggestAlternative("size", kSphereKeys),
            "expected one of: center, radius, material, transform");
  EXPECT_EQ(suggestAlternative("x", {"n", "ka"}), "expected one of: n, ka");
}

YamlNode parse(const std::string& text) { return parseYamlDocuments(text).at(0); }

TEST(Describe, ShowsValuesAsWritten) {
  EXPECT_EQ(describe(parse("abc")), "'abc'");
  EXPECT_EQ(describe(parse("-0.5")), "-0.5");
  EXPECT_EQ(describe(parse("\"1.5\"")), "the string \"1.5\"");
  EXPECT_EQ(describe(parse("[1, 2]")), "[1, 2]");
  EXPECT_EQ(describe(parse("[[1, 2], [3]]")), "a list of 2 items");
  EXPECT_EQ(describe(parse("{a: 1, b: 2}")), "a map with the keys a, b");
  EXPECT_EQ(describe(parse("a:").entries().at(0).second), "empty");
}

TEST(ReadNumber, AcceptsOnlyFiniteNumbersWithinTheBound) {
  const auto read = [](const std::string& text, Bound bound) {
    return readNumber(makeField(parse(text), "'x' in test", Mark()), bound);
  };
  EXPECT_EQ(read("2.5", Bound::Positive), 2.5f);
  EXPECT_EQ(read("0", Bound::NonNegative), 0.0f);
  EXPECT_THROW(read("0", Bound::Positive), YamlValueError);
  EXPECT_THROW(read(".nan", Bound::Any), YamlValueError);
  EXPECT_THROW(read("1e39", Bound::Any), YamlValueError);
  EXPECT_THROW(read("'2'", Bound::Any), YamlValueError);
}

}  // namespace
}  // namespace rise
