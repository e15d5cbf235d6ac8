// Small text helpers that readers and writers of files share.
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

}  // namespace rise
