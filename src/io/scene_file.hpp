// The scene file: a YAML (or JSON) description of the image, the camera, the
// lights, the materials and the objects. Loading validates all of it, so that
// every algorithm renders a scene that makes sense; the first problem found is
// thrown as a SceneError that points at the offending place in the file.
// examples/classic.yaml shows every kind of entry.
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <string_view>

#include "io/scene_error.hpp"
#include "scene/scene.hpp"

namespace rise {

// Scene files (and streams) larger than kLargestSceneFile are refused.
Scene loadSceneFile(const std::filesystem::path& path);
Scene loadSceneStream(std::istream& in, std::string sourceName);

// Loads a scene from text; sourceName names it in messages ("<stdin>").
Scene loadScene(std::string_view text, std::string sourceName);

}  // namespace rise
