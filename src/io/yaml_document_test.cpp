#include "io/yaml_document.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rise {
namespace {

YamlNode parse(const std::string& text) { return parseYamlDocuments(text).at(0); }

// "line:column: message" of the syntax error `text` raises, or "" when it parses.
std::string syntaxError(const std::string& text) {
  try {
    parseYamlDocuments(text);
  } catch (const YamlError& error) {
    return std::to_string(error.mark().line + 1) + ":" + std::to_string(error.mark().column + 1) +
           ": " + error.what();
  }
  return "";
}

TEST(YamlDocument, BuildsMapsListsAndScalarsWithTheirPlaces) {
  const YamlNode root = parse("a: [1, 'two']\nb:\n  - {c: 3}\n");
  ASSERT_TRUE(root.isMap());
  ASSERT_EQ(root.size(), 2u);
  const auto& [a, list] = root.entries()[0];
  EXPECT_EQ(a.scalar(), "a");
  ASSERT_TRUE(list.isSequence());
  EXPECT_EQ(list.mark().line, 0);
  EXPECT_EQ(list.mark().column, 3);
  EXPECT_FALSE(list.items()[0].isQuoted());
  EXPECT_TRUE(list.items()[1].isQuoted());
  const YamlNode& inner = root.entries()[1].second.items().at(0);
  ASSERT_TRUE(inner.isMap());
  EXPECT_EQ(inner.mark().line, 2);
  EXPECT_EQ(inner.mark().column, 4);
}

TEST(YamlDocument, ReadsThePlainNullsAsEmpty) {
  const YamlNode root = parse("a:\nb: ~\nc: null\nd: ''\n");
  EXPECT_TRUE(root.entries()[0].second.isNull());
  EXPECT_TRUE(root.entries()[1].second.isNull());
  EXPECT_TRUE(root.entries()[2].second.isNull());
  EXPECT_TRUE(root.entries()[3].second.isScalar());
}

TEST(YamlDocument, ReadsNumbersAsYamlWritesThem) {
  const auto number = [](const std::string& text) { return parse(text).number(); };
  EXPECT_EQ(number("2.5"), 2.5);
  EXPECT_EQ(number("-3"), -3.0);
  EXPECT_EQ(number("+.5"), 0.5);
  EXPECT_EQ(number("5."), 5.0);
  EXPECT_EQ(number("1e3"), 1000.0);
  EXPECT_EQ(number("-.inf"), -INFINITY);
  EXPECT_EQ(number("1e400"), INFINITY);
  EXPECT_EQ(number("1e-400"), 0.0);
  EXPECT_TRUE(std::isnan(*number(".nan")));
  for (const std::string notANumber : {"inf", "nan", "0x10", "1_000", "1e", ".", "'2'", "1.2.3"})
    EXPECT_FALSE(number(notANumber)) << notANumber;
}

TEST(YamlDocument, AnAliasIsTheNodeOfItsAnchor) {
  const YamlNode root = parse("a: &p [1, 2, 3]\nb: *p\n");
  EXPECT_EQ(root.entries()[1].second.size(), 3u);
  EXPECT_EQ(
      syntaxError("a: *p\n"),
      "1:4: invalid YAML: unknown alias '*p'; expected the name of an anchor '&p' given to a value "
      "before it");
}

TEST(YamlDocument, ACommaWhereAValueShouldStartIsLocated) {
  EXPECT_EQ(syntaxError(",\n"),
            "1:1: invalid YAML: unexpected ','; expected a value (quote text that starts with it)");
  EXPECT_EQ(syntaxError("# a comment\n,\n"),
            "2:1: invalid YAML: unexpected ','; expected a value (quote text that starts with it)");
  EXPECT_EQ(syntaxError("["), "2:1: invalid YAML: the text ends where a value was expected");
}

TEST(YamlDocument, RefusesNestingDeeperThanTheLimit) {
  const std::string deepest(kDeepestYamlNesting, '[');
  EXPECT_EQ(syntaxError(deepest + std::string(kDeepestYamlNesting, ']')), "");
  EXPECT_EQ(syntaxError(deepest + "[[[[" + std::string(100000, '[')),
            "1:65: lists and maps nested more than 64 deep; a scene needs only a few levels");
}

TEST(YamlDocument, RefusesMoreValuesThanTheLimit) {
  std::string values;
  for (std::size_t i = 0; i <= kMostYamlValues; ++i) values += "1,";
  EXPECT_EQ(syntaxError("[" + values + "1]").substr(0, 35), "1:2000000: more than 1000000 values");
}

TEST(YamlDocument, SaysWhatIsWrongInTheWordsOfAScene) {
  EXPECT_EQ(
      syntaxError("a: [1, 2}\n"),
      "1:9: invalid YAML: unexpected '}'; check that the brackets before it are closed in order");
  EXPECT_EQ(
      syntaxError("a: {b: 1]\n"),
      "1:9: invalid YAML: unexpected ']'; check that the brackets before it are closed in order");
  EXPECT_EQ(syntaxError("a: {b: 1\nc: 2\n"),
            "2:2: invalid YAML: a map opened with '{' is not closed with '}'");
  EXPECT_EQ(syntaxError("a: \"open\nb: 1\n"), "1:4: invalid YAML: a quoted text is not closed");
  EXPECT_EQ(syntaxError("a: 1\nb\nc: 2\n"),
            "2:1: invalid YAML: expected 'key: value' on this line; a value on a line of its own "
            "is indented "
            "under its key");
  EXPECT_EQ(syntaxError("a:\n\t- 1\n"),
            "2:1: invalid YAML: a tab in the indentation; YAML indents with spaces");
  EXPECT_EQ(syntaxError("a: \x01\n"),
            "1:4: invalid YAML: the text is not readable: control characters are "
            "not allowed");
  EXPECT_EQ(syntaxError("a: \xc3\x28\n"),
            "1:5: invalid YAML: the text is not readable: invalid trailing UTF-8 octet");
}

}  // namespace
}  // namespace rise
