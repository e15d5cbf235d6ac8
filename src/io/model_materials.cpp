#include "io/model_materials.hpp"

#include <assimp/material.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/text.hpp"
#include "io/assimp_library.hpp"
#include "io/mesh_file.hpp"
#include "io/yaml_reader.hpp"

namespace rise {

namespace {

// Each of Assimp's keys (AI_MATKEY_...) is three values: its name, and a
// texture type and index, zero for a material's own colours and numbers.
std::optional<Color> colorOf(const AssimpFunctions& assimp, const aiMaterial& material,
                             const char* key, unsigned int type, unsigned int index) {
  aiColor4D color;
  if (assimp.aiGetMaterialColor(&material, key, type, index, &color) != aiReturn_SUCCESS)
    return std::nullopt;
  return Color(color.r, color.g, color.b);
}

std::optional<float> numberOf(const AssimpFunctions& assimp, const aiMaterial& material,
                              const char* key, unsigned int type, unsigned int index) {
  ai_real value = 0;
  unsigned int count = 1;
  if (assimp.aiGetMaterialFloatArray(&material, key, type, index, &value, &count) !=
          aiReturn_SUCCESS ||
      count != 1)
    return std::nullopt;
  return static_cast<float>(value);
}

std::string textOf(const aiString& text) { return std::string(text.data, text.length); }

void check(bool holds, const ModelMaterial& material, const std::string& key, float value,
           const std::string& expected) {
  if (!holds)
    throw MeshFileError("material " + inQuotes(material.name) + " has " + key + " " +
                        shortNumber(value) + "; expected " + expected);
}

void checkColor(const std::optional<Color>& color, const ModelMaterial& material,
                const std::string& key) {
  if (!color) return;
  for (int channel = 0; channel < 3; ++channel)
    check(std::isfinite((*color)[channel]) && (*color)[channel] >= 0.0f, material, key,
          (*color)[channel], "three numbers >= 0");
}

void checkValues(const ModelMaterial& material) {
  checkColor(material.ambient, material, "Ka");
  checkColor(material.diffuse, material, "Kd");
  checkColor(material.specular, material, "Ks");
  checkColor(material.emission, material, "Ke");
  if (material.shininess)
    check(std::isfinite(*material.shininess) && *material.shininess >= 0.0f, material, "Ns",
          *material.shininess, "a number >= 0");
  if (material.opacity)
    check(*material.opacity >= 0.0f && *material.opacity <= 1.0f, material, "d", *material.opacity,
          "a number from 0 (clear) to 1 (opaque)");
  if (material.ior)
    check(std::isfinite(*material.ior) && *material.ior > 0.0f, material, "Ni", *material.ior,
          "an index of refraction > 0");
}

}  // namespace

std::optional<ModelMaterial> readModelMaterial(const AssimpFunctions& assimp,
                                               const aiMaterial& material) {
  aiString name;
  if (assimp.aiGetMaterialString(&material, AI_MATKEY_NAME, &name) != aiReturn_SUCCESS ||
      textOf(name) == AI_DEFAULT_MATERIAL_NAME)
    return std::nullopt;
  ModelMaterial read;
  read.name = textOf(name);
  read.ambient = colorOf(assimp, material, AI_MATKEY_COLOR_AMBIENT);
  read.diffuse = colorOf(assimp, material, AI_MATKEY_COLOR_DIFFUSE);
  read.specular = colorOf(assimp, material, AI_MATKEY_COLOR_SPECULAR);
  read.emission = colorOf(assimp, material, AI_MATKEY_COLOR_EMISSIVE);
  read.shininess = numberOf(assimp, material, AI_MATKEY_SHININESS);
  read.opacity = numberOf(assimp, material, AI_MATKEY_OPACITY);
  read.ior = numberOf(assimp, material, AI_MATKEY_REFRACTI);
  aiString texture;
  if (assimp.aiGetMaterialTexture(&material, aiTextureType_DIFFUSE, 0, &texture, nullptr, nullptr,
                                  nullptr, nullptr, nullptr, nullptr) == aiReturn_SUCCESS &&
      texture.length > 0)
    read.diffuseTexture = std::filesystem::path(textOf(texture));
  checkValues(read);
  return read;
}

Material asSceneMaterial(const ModelMaterial& model) {
  Material material;
  material.name = model.name;
  if (model.diffuse) {
    material.color = *model.diffuse;
    material.kd = 1.0f;
  }
  if (model.ambient) {
    const float diffuse = maxComponent(material.color);
    material.ka = diffuse > 0.0f ? std::min(maxComponent(*model.ambient) / diffuse, 1.0f) : 0.0f;
  }
  if (model.specular) material.ks = maxComponent(*model.specular);
  if (model.shininess) material.n = *model.shininess;
  if (model.emission) material.emission = *model.emission;
  if (model.opacity) material.transmission = 1.0f - *model.opacity;
  if (model.ior && material.isTransparent()) material.ior = *model.ior;
  return material;
}

}  // namespace rise
