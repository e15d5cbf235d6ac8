#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rise::cli {

// A file a command will write, and the option that named it ("-o",
// "--stats", "--aov depth").
struct PlannedOutput {
  std::filesystem::path path;
  std::string option;
};

// What is wrong with the files a command will write, found before it renders
// so that a wrong option costs no render: a file that is a folder, or in a
// folder that does not exist (unless the command makes it), the scene file
// itself, or one file named twice. Empty when every file can be written.
std::string outputsProblem(const std::vector<PlannedOutput>& outputs, const std::string& scenePath,
                           bool foldersAreMade = false);

}  // namespace rise::cli
