// The help as a student reads it: each option with a word for its value
// ("--width N", "--pattern NAME"), and what it takes said in words after its
// description ("a whole number from 1 to 32768; default 8", "one of: box,
// gaussian, tent"), instead of the parser's notation ("INT:in [1, 32768]=8",
// "--no-cull{false}").
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace rise::cli {

class HelpInWords final : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* option, bool positional) const override;
  std::string make_option_opts(const CLI::Option* option) const override;
  std::string make_option_desc(const CLI::Option* option) const override;
};

}  // namespace rise::cli
