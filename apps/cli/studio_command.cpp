#include "studio_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace rise::cli {

int startStudio(const std::vector<std::string>& arguments) {
  constexpr int kExitBadInput = 2;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path studio = self.parent_path() / "rise-studio";
  if (error || !std::filesystem::exists(studio)) {
    std::cerr << "rise: this build has no studio: Dear ImGui, GLFW or OpenGL was not found when "
                 "it was built (scripts/install-deps installs them; then build again)\n";
    return kExitBadInput;
  }
  std::vector<std::string> words{studio.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  execv(studio.c_str(), argv.data());
  std::cerr << "rise: cannot start " << studio.string() << ": " << std::strerror(errno) << "\n";
  return kExitBadInput;
}

}  // namespace rise::cli
