// The `mapping` of an object in a scene file, the texture coordinates it
// wears (scene/projected_mapping.hpp):
//
//   mapping: spherical                          uv, spherical, cylindrical, planar or box
//   mapping: {cylindrical: {axis: [0, 0, 1]}}   the axis of a turning mapping (y by default)
//
// uv, the default, is the shape's own coordinates (or a model file's).
#pragma once

#include <optional>

#include "io/yaml_reader.hpp"
#include "scene/textures/projected_mapping.hpp"

namespace rise {

// The projected mapping named, or nothing for uv.
std::optional<Mapping> readMapping(const Field& field);

}  // namespace rise
