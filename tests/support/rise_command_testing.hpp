// Running the `rise` command as a user types it, in a folder of its own.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "support/temporary_folder_testing.hpp"

namespace rise {

struct CommandResult {
  int status;
  std::string output;  // standard output and standard error together
};

// Runs a shell command line, its standard error joined to its output.
inline CommandResult runCommand(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), output};
}

inline CommandResult runRise(const std::string& arguments) {
  return runCommand(std::string(RISE_EXECUTABLE) + " " + arguments);
}

inline std::string example(const std::string& name) {
  return std::string(RISE_SOURCE_DIR) + "/examples/" + name;
}

class RiseCommand : public TemporaryFolderTest {
 protected:
  std::filesystem::path file(const std::string& name) const { return directory_ / name; }
};

}  // namespace rise
