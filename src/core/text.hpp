// Small text helpers: names matched regardless of case, and lists of names
// as messages and steps show them.
#pragma once

#include <algorithm>
#include <cctype>
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

}  // namespace rise
