// Checks of an option's number that say, as CLI11 shows them after the
// option's name, the value given and what was expected of it: "--width: 0;
// expected a whole number from 1 to 32768".
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace rise::cli {

// A whole number from `least` to `most`; with no `most`, at least `least`.
template <typename Number>
CLI::Validator wholeNumberFrom(Number least, Number most = std::numeric_limits<Number>::max()) {
  const bool bounded = most != std::numeric_limits<Number>::max();
  const std::string expected =
      "expected a whole number " +
      (bounded ? "from " + std::to_string(least) + " to " + std::to_string(most)
               : ">= " + std::to_string(least));
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        Number value{};
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && value >= least &&
            value <= most)
          return {};
        return text + "; " + expected;
      },
      bounded ? "in [" + std::to_string(least) + ", " + std::to_string(most) + "]"
              : ">= " + std::to_string(least));
}

// A number from `least` to `most`.
inline CLI::Validator numberFrom(double least, double most) {
  const auto shown = [](double value) {
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
  };
  const std::string range = shown(least) + " to " + shown(most);
  return CLI::Validator(
      [=](const std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && value >= least &&
            value <= most)
          return {};
        return text + "; expected a number from " + range;
      },
      "in [" + range + "]");
}

}  // namespace rise::cli
