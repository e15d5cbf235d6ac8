// The files a scene names, and what reading them had to say: the folder its
// models and images are found from, the textures read (each once, however
// many materials name it), and the warnings of files read with a fix (a skin
// whose palette lacks its marker byte), which loading accepts but the person
// who wrote the scene should hear of.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "io/image_io.hpp"
#include "io/yaml_document.hpp"
#include "scene/textures/image_texture.hpp"

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

  // The image at `path` (from path()) as a texture, read and prepared for
  // its filter (its mipmap, its sums) the first time it is asked for with
  // that encoding and filter: twelve materials naming one 8K texture hold one
  // copy. Its warnings go to `warnings` the first time only.
  std::shared_ptr<const ImageTexture> imageTexture(const std::filesystem::path& path,
                                                   Encoding encoding, TextureFilter filter,
                                                   std::vector<std::string>& warnings) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    const TextureKey key{error ? path : canonical, encoding, filter};
    if (const auto read = textures_.find(key); read != textures_.end()) return read->second;
    auto texture = std::make_shared<const ImageTexture>(
        std::make_shared<const Image>(readImage(path, encoding, &warnings)), filter);
    textures_.emplace(key, texture);
    return texture;
  }

  void warn(Mark mark, const std::vector<std::string>& messages) {
    for (const std::string& message : messages) warnings_.push_back({mark, message});
  }
  const std::vector<Warning>& warnings() const { return warnings_; }

 private:
  std::filesystem::path folder_;
  using TextureKey = std::tuple<std::filesystem::path, Encoding, TextureFilter>;
  std::map<TextureKey, std::shared_ptr<const ImageTexture>> textures_;
  std::vector<Warning> warnings_;
};

}  // namespace rise
