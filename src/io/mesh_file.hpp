// Triangle meshes read from model files through the Open Asset Import Library
// (Assimp): Wavefront OBJ, Stanford PLY, Quake II MD2, glTF, OFF, 3DS and STL,
// and no other of the formats Assimp reads. A file's meshes are merged into
// one (or into one for each of the file's materials), each placed by the
// transforms of the nodes above it, so that the model stands as its author
// built it (Assimp turns MD2's z-up models y-up this way).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/model_materials.hpp"
#include "scene/mesh_geometry.hpp"

namespace rise {

// Why a model file cannot be used; the scene loader adds which file, and
// where the scene names it.
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The triangles of the model in `path`, with a unit normal at every vertex
// (the file's, or, where it has none, the average of the faces around the
// vertex, except across creases sharper than kCreaseAngleDegrees) and the
// texture coordinates of its first channel when it has them. `md2Keyframe`
// picks the pose of an MD2 model, whose vertices are then kept one per
// triangle corner, so that the vertices of two keyframes match one to one.
// Throws MeshFileError for a missing, unreadable, unsupported, corrupt or
// empty file.
MeshGeometry loadMeshFile(const std::filesystem::path& path, int md2Keyframe = 0);

// The triangles of a model that wear one of its materials.
struct ModelPart {
  MeshGeometry geometry;
  std::optional<ModelMaterial> material;  // none where the file describes none
};

// The model in `path` as loadMeshFile reads it (the pose of an MD2 model's
// first keyframe), in parts: one for each material that its triangles wear,
// in the order of the file's materials.
std::vector<ModelPart> loadModelParts(const std::filesystem::path& path);

inline constexpr float kCreaseAngleDegrees = 80.0f;

// Whether the file is a Quake II model, by its extension.
bool isMd2File(const std::filesystem::path& path);

// The number of keyframes of an MD2 model, from its header, each field of
// which is checked against the file.
int md2KeyframeCount(const std::filesystem::path& path);

// The skin of an MD2 model, found in the model's folder: the first skin its
// header names (by file name, as the names are paths in the game's
// archive), else the PCX image named like the model, else the folder's only
// PCX image (Quake II keeps a model's skins beside its tris.md2).
std::optional<std::filesystem::path> findMd2Skin(const std::filesystem::path& model);

// The keyframes of an MD2 model from `first` to `last` (downwards when last
// comes first): the same triangles in their poses.
std::vector<MeshGeometry> loadMd2Keyframes(const std::filesystem::path& path, int first, int last);

}  // namespace rise
