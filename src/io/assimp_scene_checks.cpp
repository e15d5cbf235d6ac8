#include "io/assimp_scene_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "io/mesh_file.hpp"

namespace rise {

namespace {

// Whether Assimp's FindInvalidData step drops the mesh for its points: one
// with a coordinate that is not finite, or, where faces use more than one
// point, all of them the same. Its rule as Assimp 5.2 applies it, comparing
// each point used with the one before it in the file, used or not.
bool pointsAssimpDrops(const aiMesh& mesh) {
  if (mesh.mVertices == nullptr) return false;
  std::vector<bool> unused(mesh.mNumVertices, mesh.mNumFaces != 0);
  for (unsigned int face = 0; face < mesh.mNumFaces; ++face)
    for (unsigned int corner = 0; corner < mesh.mFaces[face].mNumIndices; ++corner)
      unused[mesh.mFaces[face].mIndices[corner]] = false;
  unsigned int used = 0;
  bool differ = false;
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i) {
    if (unused[i]) continue;
    ++used;
    const aiVector3D& point = mesh.mVertices[i];
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return true;
    if (i > 0 && point != mesh.mVertices[i - 1]) differ = true;
  }
  return used > 1 && !differ;
}

}  // namespace

std::string tidied(const std::string& message) {
  std::string result;
  for (char c : message) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (space && (result.empty() || result.back() == ' ')) continue;
    result.push_back(space ? ' ' : c);
  }
  while (!result.empty() && result.back() == ' ') result.pop_back();
  return result.empty() ? "the model loader failed without saying why" : result;
}

std::string explained(const std::string& message) {
  const auto with = [&](std::string_view meaning) {
    return std::string(meaning) + " (Assimp: " + message + ")";
  };
  const auto says = [&](std::string_view words) {
    return message.find(words) != std::string::npos;
  };
  if (says("is a LINE but") || says("is a POINT but"))
    return with("a face has fewer than 3 corners (a line or a point) among faces of 3 or more");
  if (says("Mesh contains no faces")) return with("the file has no faces");
  if (says("mNumMeshes is 0")) return with("the file has no meshes");
  if (says("index out of range") || (says("mIndices") && says("out of range")))
    return with("a face refers to a vertex that the file does not have");
  if (says("bad_alloc"))
    return with("reading it needs more memory than there is; is the file corrupt?");
  if (message.starts_with("Validation failed"))
    return with("the model's data does not hold together, as in a corrupt file");
  return with("the file cannot be read as a model");
}

void checkFacesAndTheirTypes(aiScene& scene) {
  for (unsigned int i = 0; i < scene.mNumMeshes; ++i) {
    aiMesh& mesh = *scene.mMeshes[i];
    unsigned int types = 0;
    for (unsigned int face = 0; face < mesh.mNumFaces; ++face) {
      switch (mesh.mFaces[face].mNumIndices) {
        case 0:
          throw MeshFileError("face " + std::to_string(face) +
                              " has no corners, as in a corrupt file");
        case 1:
          types |= aiPrimitiveType_POINT;
          break;
        case 2:
          types |= aiPrimitiveType_LINE;
          break;
        case 3:
          types |= aiPrimitiveType_TRIANGLE;
          break;
        default:
          types |= aiPrimitiveType_POLYGON;
      }
    }
    mesh.mPrimitiveTypes = types;
  }
}

void checkSomeMeshKeepsItsPoints(const aiScene& scene) {
  const std::span<aiMesh* const> meshes(scene.mMeshes, scene.mNumMeshes);
  if (meshes.empty() || !std::all_of(meshes.begin(), meshes.end(),
                                     [](const aiMesh* mesh) { return pointsAssimpDrops(*mesh); }))
    return;
  throw MeshFileError(
      "no mesh of the file has points to draw: in each, a coordinate is not a number, or every "
      "point that its faces use is the same");
}

}  // namespace rise
