// Small text helpers: names matched regardless of case, lists of names as
// messages and steps show them, and a name from a file as a message quotes it.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace rise {

// The text with ASCII letters in lower case, for names that are matched
// regardless of case (file extensions, PLY keywords, YAML values).
inline std::string lowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

// ".png" for "Film.PNG": the extension as the formats are named.
inline std::string lowercaseExtension(const std::filesystem::path& path) {
  return lowercase(path.extension().string());
}

// Adds `item` to the end of the list in `text`, after `separator` unless
// the list is empty.
inline void appendListed(std::string& text, std::string_view separator, std::string_view item) {
  if (!text.empty()) text += separator;
  text += item;
}

// The names one after another, `separator` between each two: "a, b, c".
template <typename Names>
std::string joined(const Names& names, std::string_view separator = ", ") {
  std::string text;
  for (const auto& name : names) appendListed(text, separator, name);
  return text;
}

// A whole number with its thousands set apart by commas: "2,188".
inline std::string grouped(std::uint64_t count) {
  std::string digits = std::to_string(count);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(at, ",");
  return digits;
}

// A count with its noun, singular for one: "1 light", "3 lights", "0 lights".
// The plural is the noun with an s, or `plural` where it is not ("vertices").
inline std::string counted(std::uint64_t count, std::string_view noun,
                           std::string_view plural = {}) {
  std::string text = std::to_string(count) + " ";
  if (count == 1) return text.append(noun);
  return plural.empty() ? text.append(noun).append("s") : text.append(plural);
}

// A name or value from a file as a message quotes it, in single quotes (or
// `quote`), on
// one line: a control character (a NUL, a line end) is written as its code,
// \x00, so that it neither cuts the message short nor breaks its line, and
// a name longer than 40 letters is shortened, with its length told.
inline std::string inQuotes(std::string_view text, char quote = '\'') {
  constexpr std::size_t kLongestShown = 40;
  // Cut before a letter's first byte, not inside a letter of UTF-8.
  std::size_t end = std::min(text.size(), kLongestShown);
  while (end > 0 && end < text.size() && (static_cast<unsigned char>(text[end]) & 0xc0) == 0x80)
    --end;
  std::string shown(1, quote);
  for (const char c : text.substr(0, end)) {
    const auto code = static_cast<unsigned char>(c);
    if (code >= 0x20 && code != 0x7f) {
      shown += c;
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", code);
    shown += escaped;
  }
  if (end == text.size()) return shown + quote;
  return shown + "..." + quote + " (" + std::to_string(text.size()) + " characters)";
}

}  // namespace rise
