// The scene loader, from libyaml's tokens to a Scene: any text must end in a
// Scene or a SceneError, never in a crash, a hang or another exception.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/scene_error.hpp"
#include "io/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    rise::loadScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const rise::SceneError&) {
  }
  return 0;
}
