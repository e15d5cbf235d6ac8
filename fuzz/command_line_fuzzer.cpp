// The command line: the input's lines as the arguments of `rise`. Whatever
// they are, run returns an exit status, never crashes. scripts/fuzz runs it
// in an empty folder with nothing on standard input, where no scene exists
// but the ones the arguments cannot name.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "run.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> arguments{"rise"};
  std::string argument;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] != '\n') {
      argument += static_cast<char>(data[i]);
      continue;
    }
    arguments.push_back(argument);
    argument.clear();
  }
  if (!argument.empty()) arguments.push_back(argument);
  std::vector<char*> argv;
  for (std::string& each : arguments) argv.push_back(each.data());
  argv.push_back(nullptr);
  rise::cli::run(static_cast<int>(arguments.size()), argv.data());
  return 0;
}
