// The `mesh` of a scene file's objects: a model file (MD2, OBJ, PLY, glTF,
// OFF, 3DS... through Assimp) or triangles written out in the scene.
//
//   mesh: {file: models/tris.md2, frame: 40}      one keyframe of an MD2 model
//   mesh: {file: models/tris.md2, frames: [40, 41]}  two, across the shutter
//   mesh: {vertices: [[x, y, z], ...], faces: [[0, 1, 2], ...]}
//   mesh: {file: models/box.obj}        without a material: the file's own
//
// A file's path is relative to the scene file's folder.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "io/scene_files.hpp"
#include "io/scene_materials.hpp"
#include "io/yaml_reader.hpp"
#include "scene/material.hpp"
#include "scene/shape.hpp"

namespace rise {

// The mesh, its vertices in its own space taking the object's `mapping` (so
// that the texture moves with it), then placed in the world.
std::unique_ptr<Shape> readMesh(const CheckedMap& mesh, int material, const Mat4& worldFromObject,
                                SceneFiles& files);

// "mesh: {file: models/box.obj}" without a `material`: the model in parts,
// one mesh for each material the file gives its faces (its MTL file's
// materials), taking it as asSceneMaterial makes it RISE's, named "<its
// name> of <file>" and added to `materials` once, with its map_Kd texture
// found from the model's folder. Faces the file gives no material wear
// RISE's default one; a file that describes no material at all is refused.
std::vector<std::unique_ptr<Shape>> readMeshInItsMaterials(const CheckedMap& mesh,
                                                           const Mat4& worldFromObject,
                                                           SceneMaterials& materials,
                                                           SceneFiles& files);

// The material an MD2 model wears: its own when that has a texture; else the
// same again, under the name "<material> with <skin>", with the model's skin
// (findMd2Skin) as its texture, added to `materials` once and shared by every
// model that wears the same skin.
int withMd2Skin(const CheckedMap& mesh, int material, SceneMaterials& materials, SceneFiles& files);

}  // namespace rise
