#include "io/text_position.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/yaml_document.hpp"

namespace rise {
namespace {

// "line:column" as a message shows it, counted from 1.
std::string shown(const Mark& mark) {
  return std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string syntaxError(const std::string& text) {
  try {
    parseYamlDocuments(text);
  } catch (const YamlError& error) {
    return shown(error.mark()) + ": " + error.what();
  }
  return "";
}

std::string withLineEnds(std::string text, const std::string& lineEnd) {
  std::string ended;
  for (const char c : text) ended += c == '\n' ? lineEnd : std::string(1, c);
  return ended;
}

TEST(TextPosition, EveryLineEndThatYamlReadsEndsALine) {
  for (const std::string lineEnd : {"\n", "\r\n", "\r", "\xC2\x85", "\xE2\x80\xA8"}) {
    const std::string text = withLineEnds("ab\ncd\n\nef", lineEnd);
    EXPECT_EQ(shown(characterMarkAt(text, text.find('d'))), "2:2") << lineEnd.size();
    EXPECT_EQ(shown(characterMarkAt(text, text.find('f'))), "4:2") << lineEnd.size();
    EXPECT_EQ(offsetOfCharacter(text, {3, 1}), text.find('f'));
    EXPECT_EQ(lineShown(text, 1), "cd");
    EXPECT_EQ(lineShown(text, 2), "");
  }
}

TEST(TextPosition, ATabReachesTheNextTabStop) {
  const std::string text = "\tx: [1,\t2]\n  \t y";
  ShownMarks marks(text);
  EXPECT_EQ(shown(marks.shown({0, 1})), "1:9");   // x
  EXPECT_EQ(shown(marks.shown({0, 8})), "1:17");  // 2, after a tab at column 15
  EXPECT_EQ(shown(marks.shown({1, 4})), "2:10");  // y
  EXPECT_EQ(lineShown(text, 0), "        x: [1,  2]");
  EXPECT_EQ(offsetOfShown(text, {0, 16}), text.find('2'));
  EXPECT_EQ(offsetOfShown(text, {0, 15}), text.find('\t', 1));  // inside the tab
  EXPECT_EQ(offsetOfShown(text, {0, 99}), text.find('\n'));
  EXPECT_EQ(offsetOfShown(text, {7, 0}), text.size());
}

TEST(TextPosition, ColumnsCountCharactersNotBytesAndNotTheByteOrderMark) {
  const std::string text =
      "\xEF\xBB\xBF"
      "\xC3\xA9t\xC3\xA9: x";
  EXPECT_EQ(shown(characterMarkAt(text, text.find('x'))), "1:6");
  EXPECT_EQ(offsetOfCharacter(text, {0, 5}), text.find('x'));
  EXPECT_EQ(shown(ShownMarks(text).shown({0, 5})), "1:6");
}

TEST(TextPosition, MarksAskedInAnyOrderAreShownTheSame) {
  const std::string text = "a\tb\r\n\tc\rd";
  ShownMarks marks(text);
  EXPECT_EQ(shown(marks.shown({1, 1})), "2:9");
  EXPECT_EQ(shown(marks.shown({0, 2})), "1:9");
  EXPECT_EQ(shown(marks.shown({2, 0})), "3:1");
  EXPECT_EQ(shown(marks.shown({2, 3})), "3:4");  // past the text's end: one a column
  EXPECT_EQ(shown(marks.shown({9, 2})), "10:3");
}

// The same scene with each kind of line end, and with tabs where a space
// may be: the same messages, at the places an editor shows.
TEST(TextPosition, YamlErrorsAreLocatedAlikeWithEveryLineEnd) {
  const std::string cases[][2] = {
      {"a: 1\nb:\n\tm: {}\n", "3:10: invalid YAML: unexpected ':'"},
      {"a:\n  - 1\n\t- 2\n", "3:1: invalid YAML: a tab in the indentation"},
      {"a: 1\nb: [\xff]\n", "2:5: invalid YAML: the text is not readable"},
      {"a: 1\nb: [c: {d: [0}]\n", "2:14: invalid YAML: unexpected '}'; check that the brackets"},
      {"a: 1\nb: 2\n c: 1\n", "3:3: invalid YAML: unexpected ':'"},
      {"a: 1\nb: {c:\t[1,\t*x]}\n", "2:17: invalid YAML: unknown alias '*x'"},
  };
  for (const auto& [text, message] : cases)
    for (const std::string lineEnd : {"\n", "\r\n", "\r"})
      EXPECT_TRUE(syntaxError(withLineEnds(text, lineEnd)).starts_with(message))
          << syntaxError(withLineEnds(text, lineEnd)) << " with " << lineEnd.size();
}

// A scene of one line, as a program may write it: every node's mark found
// in one pass, not one pass a node.
TEST(TextPosition, MarksOnOneLongLineAreFoundInOnePass) {
  std::string text = "[";
  for (int i = 0; i < 300000; ++i) text += "1,\t";
  text += "x]";
  const std::vector<YamlNode> documents = parseYamlDocuments(text);
  EXPECT_EQ(documents.at(0).items().back().mark().column, 300000 * 8);
}

}  // namespace
}  // namespace rise
