#include "io/mesh_file.hpp"

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <vector>

#include "core/text.hpp"
#include "io/assimp_library.hpp"
#include "io/assimp_scene_checks.hpp"
#include "io/checked_model_files.hpp"
#include "io/file_limits.hpp"
#include "io/model_headers.hpp"
#include "io/model_materials.hpp"
#include "scene/vertex_normals.hpp"

namespace rise {

namespace {

// The scene Assimp read, released through its library.
struct SceneRelease {
  decltype(&aiReleaseImport) release;
  void operator()(const aiScene* scene) const { release(scene); }
};
using AssimpScene = std::unique_ptr<const aiScene, SceneRelease>;

// The formats the manual lists, each read by Assimp's importer for it. Its
// importers for other formats are not used: several of them crash or never
// return on a corrupt file (MD5, ASE, OpenGEX, SMD).
const std::vector<std::string> kModelFormats = {".obj", ".ply", ".md2", ".gltf",
                                                ".glb", ".off", ".3ds", ".stl"};

// ".obj, .ply, ... or .stl".
std::string formatsRead() {
  const std::vector<std::string> allButLast(kModelFormats.begin(), kModelFormats.end() - 1);
  return joined(allButLast) + " or " + kModelFormats.back();
}

// The file must exist, be a regular file within the size RISE reads, open,
// and hold something.
void checkReadable(const std::filesystem::path& path) {
  if (const std::optional<std::string> problem = fileKindOrSizeProblem(path, kLargestModelFile))
    throw MeshFileError(*problem);
  errno = 0;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    const std::string cause =
        errno != 0 ? std::generic_category().message(errno) : "unknown reason";
    throw MeshFileError("cannot open the file (" + cause + ")");
  }
  if (file.peek() == std::ifstream::traits_type::eof()) throw MeshFileError("the file is empty");
}

// The first `most` bytes of a file that checkReadable passed (a regular
// file, so of a known size: no more is allocated than it holds).
std::string readStart(const std::filesystem::path& path, std::size_t most) {
  std::ifstream file(path, std::ios::binary);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::string start(error ? most : static_cast<std::size_t>(std::min<std::uintmax_t>(most, size)),
                    '\0');
  file.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(file.gcount()));
  return start;
}

std::span<const std::uint8_t> bytesOf(const std::string& text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

void checkFormatIsSupported(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension.empty())
    throw MeshFileError("the file name has no extension to tell its format; expected " +
                        formatsRead());
  if (std::find(kModelFormats.begin(), kModelFormats.end(), lowercase(extension)) ==
      kModelFormats.end())
    throw MeshFileError(inQuotes(extension) + " is not a model format that RISE reads; expected " +
                        formatsRead());
}

// The header checks of the formats whose headers promise counts: Assimp
// trusts them (and 5.2 loops forever on a PLY file that ends in its header).
void checkHeader(const std::filesystem::path& path) {
  constexpr std::size_t kLongestHeader = 1 << 20;
  const std::string extension = lowercaseExtension(path);
  if (extension == ".ply")
    checkPlyHeader(readStart(path, kLongestHeader), std::filesystem::file_size(path));
  if (extension == ".off")
    checkOffHeader(readStart(path, kLongestHeader), std::filesystem::file_size(path));
  if (extension == ".md2") checkedMd2Header(bytesOf(readStart(path, kLargestModelFile)));
}

// Assimp's C interface keeps its last error in one string for all threads:
// one model is read at a time.
std::mutex assimpReading;

AssimpScene readWithAssimp(const AssimpFunctions& assimp, const std::filesystem::path& path,
                           int md2Keyframe) {
  const std::lock_guard<std::mutex> oneAtATime(assimpReading);
  const std::unique_ptr<aiPropertyStore, decltype(&aiReleasePropertyStore)> properties(
      assimp.aiCreatePropertyStore(), assimp.aiReleasePropertyStore);
  assimp.aiSetImportPropertyInteger(properties.get(), AI_CONFIG_IMPORT_MD2_KEYFRAME, md2Keyframe);
  // Validation comes first, so that no later step reads a corrupt index.
  CheckedModelFiles files;
  AssimpScene read(assimp.aiImportFileExWithProperties(
                       path.c_str(), aiProcess_ValidateDataStructure, files.io(), properties.get()),
                   SceneRelease{assimp.aiReleaseImport});
  if (files.refused()) throw MeshFileError("cannot read a file it names: " + *files.refused());
  if (!read) throw MeshFileError(explained(tidied(assimp.aiGetErrorString())));
  // Assimp owns the scene it read and lets it be changed between steps.
  checkFacesAndTheirTypes(const_cast<aiScene&>(*read));
  checkSomeMeshKeepsItsPoints(*read);
  // Invalid normals (all zero, NaN) are dropped, to be computed like missing
  // ones. RISE computes those itself: Assimp's smoothing cannot split a
  // vertex that faces share across a crease (the corners of an OFF box).
  // A step that fails releases the scene itself.
  AssimpScene scene(assimp.aiApplyPostProcessing(read.release(),
                                                 aiProcess_Triangulate | aiProcess_FindInvalidData),
                    SceneRelease{assimp.aiReleaseImport});
  if (!scene) throw MeshFileError(explained(tidied(assimp.aiGetErrorString())));
  return scene;
}

Vec3 toVec3(const aiVector3D& v) { return Vec3(v.x, v.y, v.z); }

// Assimp's matrices are row-major, glm's column-major.
Mat4 toMat4(const aiMatrix4x4& m) {
  Mat4 result;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) result[column][row] = m[row][column];
  return result;
}

// One Assimp mesh in its own space: its triangles (points and lines are left
// out) and a unit normal at each vertex: the file's, zero where one of them is
// unusable, or computed when the file has none. Assimp gives each corner of a
// face a vertex of its own; they are joined again (`joinVertices`), but for
// an MD2 model, whose keyframes must keep the same vertices however their
// points meet.
MeshGeometry geometryOf(const aiMesh& mesh, bool joinVertices) {
  MeshGeometry geometry;
  geometry.positions.reserve(mesh.mNumVertices);
  if (mesh.HasNormals()) geometry.normals.reserve(mesh.mNumVertices);
  if (mesh.HasTextureCoords(0)) geometry.uvs.reserve(mesh.mNumVertices);
  geometry.triangles.reserve(mesh.mNumFaces);
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i) {
    geometry.positions.push_back(toVec3(mesh.mVertices[i]));
    if (mesh.HasNormals()) {
      const Vec3 normal = toVec3(mesh.mNormals[i]);
      geometry.normals.push_back(isFinite(normal) ? normalizedOrZero(normal) : Vec3(0.0f));
    }
    if (mesh.HasTextureCoords(0))
      geometry.uvs.emplace_back(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y);
  }
  for (unsigned int i = 0; i < mesh.mNumFaces; ++i) {
    const aiFace& face = mesh.mFaces[i];
    if (face.mNumIndices != 3) continue;
    std::array<int, 3> triangle;
    for (int corner = 0; corner < 3; ++corner) {
      if (face.mIndices[corner] >= mesh.mNumVertices)
        throw MeshFileError("a face refers to a vertex that the mesh does not have");
      triangle[corner] = static_cast<int>(face.mIndices[corner]);
    }
    geometry.triangles.push_back(triangle);
  }
  if (joinVertices) geometry = withIdenticalVerticesJoined(geometry);
  return mesh.HasNormals() ? geometry : withVertexNormals(geometry, kCreaseAngleDegrees);
}

// Where the triangles of one of the file's meshes go: the one model, or the
// part of the model that wears the mesh's material.
using PartOfMesh = std::function<MeshGeometry&(const aiMesh&)>;

// Appends the meshes of `node` and of the nodes under it, each placed by the
// transforms from the root down to its node.
void appendNode(const aiScene& scene, const aiNode& node, const Mat4& parentToFile,
                bool joinVertices, const PartOfMesh& partOf) {
  const Mat4 nodeToFile = parentToFile * toMat4(node.mTransformation);
  for (unsigned int i = 0; i < node.mNumMeshes; ++i) {
    if (node.mMeshes[i] >= scene.mNumMeshes)
      throw MeshFileError("a node refers to a mesh that the file does not have");
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    append(partOf(mesh), transformed(geometryOf(mesh, joinVertices), nodeToFile));
  }
  for (unsigned int i = 0; i < node.mNumChildren; ++i)
    appendNode(scene, *node.mChildren[i], nodeToFile, joinVertices, partOf);
}

void checkPoints(const MeshGeometry& geometry) {
  if (!std::all_of(geometry.positions.begin(), geometry.positions.end(),
                   [](const Vec3& v) { return isFinite(v); }))
    throw MeshFileError("a vertex has a coordinate that is not a finite number");
}

AssimpScene readScene(const std::filesystem::path& path, int md2Keyframe) {
  checkReadable(path);
  checkFormatIsSupported(path);
  checkHeader(path);
  return readWithAssimp(loadedAssimp(), path, md2Keyframe);
}

MeshGeometry readModel(const std::filesystem::path& path, int md2Keyframe) {
  const AssimpScene scene = readScene(path, md2Keyframe);
  MeshGeometry model;
  if (scene->mRootNode != nullptr)
    appendNode(*scene, *scene->mRootNode, Mat4(1.0f), !isMd2File(path),
               [&](const aiMesh&) -> MeshGeometry& { return model; });
  if (model.triangles.empty()) throw MeshFileError("the file has no triangles");
  checkPoints(model);
  return model;
}

std::vector<ModelPart> readModelParts(const std::filesystem::path& path) {
  const AssimpScene scene = readScene(path, 0);
  std::vector<MeshGeometry> byMaterial(std::max(scene->mNumMaterials, 1u));
  if (scene->mRootNode != nullptr)
    appendNode(
        *scene, *scene->mRootNode, Mat4(1.0f), !isMd2File(path),
        [&](const aiMesh& mesh) -> MeshGeometry& {
          return byMaterial[mesh.mMaterialIndex < byMaterial.size() ? mesh.mMaterialIndex : 0];
        });
  std::vector<ModelPart> parts;
  for (std::size_t i = 0; i < byMaterial.size(); ++i) {
    if (byMaterial[i].triangles.empty()) continue;
    checkPoints(byMaterial[i]);
    std::optional<ModelMaterial> material;
    if (i < scene->mNumMaterials && scene->mMaterials[i] != nullptr)
      material = readModelMaterial(loadedAssimp(), *scene->mMaterials[i]);
    parts.push_back({std::move(byMaterial[i]), std::move(material)});
  }
  if (parts.empty()) throw MeshFileError("the file has no triangles");
  return parts;
}

// Assimp reports its failures by returning no scene, but a corrupt count can
// still make it ask for more memory than there is.
template <typename Read>
auto withFailuresExplained(const Read& read) {
  try {
    return read();
  } catch (const MeshFileError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw MeshFileError("reading it needs more memory than there is; is the file corrupt?");
  } catch (const std::exception& error) {
    throw MeshFileError(explained(tidied(error.what())));
  }
}

}  // namespace

MeshGeometry loadMeshFile(const std::filesystem::path& path, int md2Keyframe) {
  return withFailuresExplained([&] { return readModel(path, md2Keyframe); });
}

std::vector<ModelPart> loadModelParts(const std::filesystem::path& path) {
  return withFailuresExplained([&] { return readModelParts(path); });
}

std::optional<std::filesystem::path> findMd2Skin(const std::filesystem::path& model) {
  const std::filesystem::path folder = model.parent_path();
  std::vector<std::filesystem::path> candidates;
  try {
    checkReadable(model);
    const std::string file = readStart(model, kLargestModelFile);
    for (const std::string& name : md2SkinNames(checkedMd2Header(bytesOf(file)), bytesOf(file)))
      candidates.push_back(folder / std::filesystem::path(name).filename());
  } catch (const MeshFileError&) {
    // Loading the model says what is wrong with it; its skin can be found without its names.
  }
  candidates.push_back(folder / (model.stem().string() + ".pcx"));
  for (const std::filesystem::path& candidate : candidates)
    if (std::filesystem::is_regular_file(candidate)) return candidate;
  std::vector<std::filesystem::path> images;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(
           folder.empty() ? std::filesystem::path(".") : folder, error))
    if (entry.is_regular_file() && lowercaseExtension(entry.path()) == ".pcx")
      images.push_back(entry.path());
  if (images.size() == 1) return images.front();
  return std::nullopt;
}

bool isMd2File(const std::filesystem::path& path) { return lowercaseExtension(path) == ".md2"; }

int md2KeyframeCount(const std::filesystem::path& path) {
  checkReadable(path);
  return static_cast<int>(
      checkedMd2Header(bytesOf(readStart(path, kLargestModelFile))).frames.count);
}

std::vector<MeshGeometry> loadMd2Keyframes(const std::filesystem::path& path, int first, int last) {
  const int step = last >= first ? 1 : -1;
  std::vector<MeshGeometry> keyframes;
  for (int keyframe = first; keyframe != last + step; keyframe += step) {
    keyframes.push_back(loadMeshFile(path, keyframe));
    const MeshGeometry& start = keyframes.front();
    const MeshGeometry& pose = keyframes.back();
    if (start.triangles != pose.triangles || start.positions.size() != pose.positions.size() ||
        start.normals.size() != pose.normals.size())
      throw MeshFileError("keyframes " + std::to_string(first) + " and " +
                          std::to_string(keyframe) + " do not share their triangles");
  }
  return keyframes;
}

}  // namespace rise
