// The `objects` of a scene file: each a shape with its material, and its
// placement, motion and texture mapping.
//
//   - sphere: {center: [0, 1, 0], radius: 1, material: red,
//              transform: {rotate: [0, 30, 0]}, motion: {translate: [0.2, 0, 0]},
//              mapping: spherical}
//
// Shapes: plane, sphere, box, cylinder, cone, triangle, polygon and mesh
// (mesh_reader.hpp).
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

// The shape of one item of `objects`: one, or, for a model file that wears
// its own materials, one for each of them (readMeshInItsMaterials). An MD2
// model may add the material that wears its skin to `materials`
// (withMd2Skin), a model file its own materials.
std::vector<std::unique_ptr<Shape>> readObject(const Field& item, SceneMaterials& materials,
                                               SceneFiles& files);

// The object as a student finds it in the file: its kind and line, "sphere
// at line 16". For an item that readObject has read.
std::string describeObject(const Field& item);

}  // namespace rise
