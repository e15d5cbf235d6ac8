// The model loaders through RISE's own checks (MD2 headers, PLY and OFF
// counts) and then Assimp's importers for the formats RISE reads; a format
// it does not read is refused by name. Any file must end in a mesh or a
// MeshFileError.
#include <array>
#include <cstddef>
#include <cstdint>

#include "input_file.hpp"
#include "io/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static constexpr std::array kExtensions{".md2", ".obj", ".ply", ".off", ".stl", ".gltf", ".glb", ".3ds", ".md5mesh"};
  const std::filesystem::path path = rise::fuzz::writeInputFile(data, size, kExtensions);
  try {
    if (rise::isMd2File(path) && rise::md2KeyframeCount(path) > 1)
      rise::loadMd2Keyframes(path, 0, 1);
    else
      rise::loadMeshFile(path);
  } catch (const rise::MeshFileError&) {
  }
  return 0;
}
