#include "io/text_position.hpp"

namespace rise {
namespace {

bool isUtf8Continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// libyaml reads past a byte order mark and counts columns from after it.
std::size_t textStart(std::string_view text) { return text.starts_with("\xEF\xBB\xBF") ? 3 : 0; }

// The bytes of the character at `offset`: its first and those continuing it.
std::size_t characterBytes(std::string_view text, std::size_t offset) {
  std::size_t end = offset + 1;
  while (end < text.size() && isUtf8Continuation(text[end])) ++end;
  return end - offset;
}

int shownAfter(int shownColumn, char c) {
  return c == '\t' ? (shownColumn / kTabStop + 1) * kTabStop : shownColumn + 1;
}

// The first byte of line `line`, or nothing when the text has fewer lines.
std::optional<std::size_t> lineStart(std::string_view text, int line) {
  std::size_t offset = textStart(text);
  for (int at = 0; at < line; ++at) {
    while (offset < text.size() && lineBreakAt(text, offset) == 0) ++offset;
    if (offset >= text.size()) return std::nullopt;
    offset += lineBreakAt(text, offset);
  }
  return offset;
}

}  // namespace

std::size_t lineBreakAt(std::string_view text, std::size_t offset) {
  const std::string_view rest = text.substr(std::min(offset, text.size()));
  if (rest.starts_with("\r\n")) return 2;
  if (rest.starts_with('\r') || rest.starts_with('\n')) return 1;
  if (rest.starts_with("\xC2\x85")) return 2;  // next line
  if (rest.starts_with("\xE2\x80\xA8") || rest.starts_with("\xE2\x80\xA9")) return 3;
  return 0;
}

std::optional<std::size_t> offsetOfCharacter(std::string_view text, Mark characters) {
  const std::optional<std::size_t> start = lineStart(text, characters.line);
  if (!start) return std::nullopt;
  std::size_t offset = *start;
  for (int column = 0; column < characters.column; ++column) {
    if (offset >= text.size() || lineBreakAt(text, offset) > 0) return std::nullopt;
    offset += characterBytes(text, offset);
  }
  if (offset >= text.size()) return std::nullopt;
  return offset;
}

Mark characterMarkAt(std::string_view text, std::size_t offset) {
  Mark mark;
  std::size_t at = textStart(text);
  while (at < offset && at < text.size()) {
    if (const std::size_t lineBreak = lineBreakAt(text, at); lineBreak > 0) {
      if (offset < at + lineBreak) break;
      ++mark.line;
      mark.column = 0;
      at += lineBreak;
    } else {
      ++mark.column;
      at += characterBytes(text, at);
    }
  }
  return mark;
}

std::size_t offsetOfShown(std::string_view text, Mark shown) {
  std::size_t offset = lineStart(text, shown.line).value_or(text.size());
  for (int column = 0; offset < text.size() && lineBreakAt(text, offset) == 0;) {
    column = shownAfter(column, text[offset]);
    if (column > shown.column) break;
    offset += characterBytes(text, offset);
  }
  return offset;
}

std::string lineShown(std::string_view text, int line) {
  std::string shown;
  const std::optional<std::size_t> start = lineStart(text, line);
  for (std::size_t offset = start.value_or(text.size());
       offset < text.size() && lineBreakAt(text, offset) == 0; ++offset) {
    if (text[offset] == '\t')
      shown.append(static_cast<std::size_t>(kTabStop) - shown.size() % kTabStop, ' ');
    else
      shown += text[offset];
  }
  return shown;
}

ShownMarks::ShownMarks(std::string_view text) : text_(text), offset_(textStart(text)) {}

Mark ShownMarks::shown(Mark characters) {
  if (characters.line < characters_.line ||
      (characters.line == characters_.line && characters.column < characters_.column))
    *this = ShownMarks(text_);
  while (characters_.line < characters.line && offset_ < text_.size()) {
    while (offset_ < text_.size() && lineBreakAt(text_, offset_) == 0) ++offset_;
    if (offset_ >= text_.size()) break;
    offset_ += lineBreakAt(text_, offset_);
    ++characters_.line;
    characters_.column = 0;
    shownColumn_ = 0;
  }
  if (characters_.line < characters.line) return characters;  // beyond the text
  while (characters_.column < characters.column && offset_ < text_.size() &&
         lineBreakAt(text_, offset_) == 0) {
    shownColumn_ = shownAfter(shownColumn_, text_[offset_]);
    offset_ += characterBytes(text_, offset_);
    ++characters_.column;
  }
  // A mark past the line's last character (its end) counts on one a column.
  return {characters.line, shownColumn_ + (characters.column - characters_.column)};
}

}  // namespace rise
