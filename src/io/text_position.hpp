// Places in a scene's text, as a reader finds them. Lines end where YAML
// ends them: at a line feed, a carriage return and line feed, a lone
// carriage return (old Mac files) or a Unicode line break, as libyaml counts
// them. Columns are those an editor or a compiler shows (the GNU coding
// standards' convention): each character one column, and a tab reaching to
// the next multiple of 8. libyaml's own marks count characters, a tab one;
// messages, and the studio's cursor, use the columns shown.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rise {

// A place in a text: 0-based line and column.
struct Mark {
  int line = 0;
  int column = 0;
};

inline constexpr int kTabStop = 8;

// The bytes of the line break at `offset` (2 for CR LF), 0 when none is there.
std::size_t lineBreakAt(std::string_view text, std::size_t offset);

// The byte of the text at a mark whose column counts characters (libyaml's),
// or nothing when the text has no character there.
std::optional<std::size_t> offsetOfCharacter(std::string_view text, Mark characters);

// The mark, its column counting characters, of the byte at `offset`.
Mark characterMarkAt(std::string_view text, std::size_t offset);

// The byte of the text where a shown mark (line, and column as shown) points:
// the end of the line when the line is shorter, the end of the text when
// the text has fewer lines.
std::size_t offsetOfShown(std::string_view text, Mark shown);

// Line `line` of the text without its break, each tab widened to the spaces
// that reach its tab stop, so that a caret under a shown column lines up.
std::string lineShown(std::string_view text, int line);

// libyaml's marks (columns in characters) turned into shown ones. Marks asked
// for in the order of the text (as a parser meets them) cost, all together,
// one pass over the text, however long its lines.
class ShownMarks {
 public:
  explicit ShownMarks(std::string_view text);
  Mark shown(Mark characters);

 private:
  std::string_view text_;
  // A place reached: the byte, its line and its column in both counts.
  std::size_t offset_ = 0;
  Mark characters_;
  int shownColumn_ = 0;
};

}  // namespace rise
