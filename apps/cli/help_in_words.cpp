#include "help_in_words.hpp"

#include <string_view>

#include "core/text.hpp"

namespace rise::cli {
namespace {

// The parser's name of the value's type, and what its checks say of it:
// "INT" and "in [1, 32768]" of "INT:in [1, 32768]".
struct TypeName {
  std::string type;
  std::string checks;
};

TypeName typeNameOf(const CLI::Option* option) {
  const std::string name = option->get_type_name();
  const std::size_t colon = name.find(':');
  if (colon == std::string::npos) return {name, ""};
  return {name.substr(0, colon), name.substr(colon + 1)};
}

bool isWholeNumber(std::string_view type) { return type == "INT" || type == "UINT"; }

// "in [1, 32768]" as "a whole number from 1 to 32768", "{a, b}" as "one of:
// a, b", "> 0" as "a number above 0".
std::string checksInWords(const TypeName& name) {
  const std::string_view checks = name.checks;
  const std::string number = isWholeNumber(name.type) ? "a whole number" : "a number";
  if (checks.starts_with("in [") && checks.ends_with("]")) {
    std::string range(checks.substr(4, checks.size() - 5));
    if (const std::size_t comma = range.find(", "); comma != std::string::npos)
      range.replace(comma, 2, " to ");
    return number + " from " + range;
  }
  if (checks.starts_with("{") && checks.ends_with("}")) {
    std::string choices(checks.substr(1, checks.size() - 2));
    for (std::size_t comma = choices.find(','); comma != std::string::npos;
         comma = choices.find(',', comma + 1))
      if (comma + 1 < choices.size() && choices[comma + 1] != ' ') choices.insert(comma + 1, " ");
    return "one of: " + choices;
  }
  if (checks.starts_with(">= ")) return number + ", " + std::string(checks.substr(3)) + " or more";
  if (checks.starts_with("> ")) return number + " above " + std::string(checks.substr(2));
  return std::string(checks);
}

// A word for the value: N for a whole number, X for any number, NAME for
// one of some words, FILE for text (RISE's text options name files).
std::string valueWord(const CLI::Option* option) {
  const TypeName name = typeNameOf(option);
  if (name.checks.starts_with("{")) return "NAME";
  if (isWholeNumber(name.type)) return "N";
  if (name.type == "FLOAT") return "X";
  return name.type.empty() || name.type == "TEXT" ? "FILE" : name.type;
}

}  // namespace

std::string HelpInWords::make_option_name(const CLI::Option* option, bool positional) const {
  if (positional) return option->get_name(true);
  std::string names;
  for (const std::string& name : option->get_snames()) appendListed(names, ",", "-" + name);
  for (const std::string& name : option->get_lnames()) appendListed(names, ",", "--" + name);
  return names;
}

std::string HelpInWords::make_option_opts(const CLI::Option* option) const {
  if (!option->get_option_text().empty()) return " " + option->get_option_text();
  if (option->get_expected_max() == 0 || option->get_positional()) return "";
  std::string word = valueWord(option);
  if (option->get_expected_min() > 1) {
    std::string words;
    for (int i = 0; i < option->get_expected_min(); ++i) appendListed(words, ",", word);
    word = words;
  }
  if (option->get_expected_max() == CLI::detail::expected_max_vector_size) word += ",...";
  return " " + word;
}

std::string HelpInWords::make_option_desc(const CLI::Option* option) const {
  std::string description = option->get_description();
  std::string takes;
  if (option->get_expected_max() != 0) {
    appendListed(takes, "; ", checksInWords(typeNameOf(option)));
    if (!option->get_default_str().empty())
      appendListed(takes, "; ", "default " + option->get_default_str());
  }
  if (option->get_required() && !option->get_positional()) appendListed(takes, "; ", "required");
  if (!takes.empty()) appendListed(description, "; ", takes);
  return description;
}

}  // namespace rise::cli
