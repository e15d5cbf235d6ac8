// The materials a model file gives its faces (an OBJ's MTL file, a glTF's
// materials, a 3DS file's), as Assimp reads them, in the file's own terms:
// the scene loader turns them into RISE's materials (io/mesh_reader.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/color.hpp"
#include "scene/material.hpp"

struct aiMaterial;

namespace rise {

struct AssimpFunctions;

// Each value is left unset where the file gives none.
struct ModelMaterial {
  std::string name;
  std::optional<Color> ambient;    // Ka
  std::optional<Color> diffuse;    // Kd
  std::optional<Color> specular;   // Ks
  std::optional<Color> emission;   // Ke
  std::optional<float> shininess;  // Ns, the Phong exponent
  std::optional<float> opacity;    // d: 1 is opaque, 0 lets all light through
  std::optional<float> ior;        // Ni
  // map_Kd, as the file names it: relative to the model's folder.
  std::optional<std::filesystem::path> diffuseTexture;
};

// The material as the file describes it, or none for the material that
// Assimp gives a model whose file describes none (an OBJ without an MTL file).
// Throws MeshFileError for a value no material can have (a negative colour,
// an opacity past 1).
std::optional<ModelMaterial> readModelMaterial(const AssimpFunctions& assimp,
                                               const aiMaterial& material);

// The same in RISE's terms, with RISE's defaults where the file is silent:
// C is Kd, with kd 1; ka is how Ka compares with Kd (the largest channel of
// each; 1 where they are the same, as in many files, and 0 without Ka); ks the largest channel
// of Ks (RISE's highlight has the light's colour) and n is Ns; the emission
// is Ke; the transmission is 1 - d, through an interior of index Ni. The
// texture (map_Kd) is the caller's to read, as it needs the scene's files.
Material asSceneMaterial(const ModelMaterial& model);

}  // namespace rise
