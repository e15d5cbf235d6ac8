// The files a scene names, and what reading them had to say: the folder its
// models and images are found from, and the warnings of files read with a
// fix (a skin whose palette lacks its marker byte), which loading accepts
// but the person who wrote the scene should hear of.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/yaml_document.hpp"

namespace rise {

class SceneFiles {
 public:
  struct Warning {
    Mark mark;  // the value that named the file
    std::string message;
  };

  explicit SceneFiles(std::filesystem::path folder) : folder_(std::move(folder)) {}

  // A file named in the scene, found from the scene file's folder.
  std::filesystem::path path(const std::string& name) const { return folder_ / name; }

  void warn(Mark mark, const std::vector<std::string>& messages) {
    for (const std::string& message : messages) warnings_.push_back({mark, message});
  }
  const std::vector<Warning>& warnings() const { return warnings_; }

 private:
  std::filesystem::path folder_;
  std::vector<Warning> warnings_;
};

}  // namespace rise
