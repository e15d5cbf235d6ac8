// The `texture` of a material in a scene file:
//
//   texture: {image: textures/map.png, filter: bilinear, scale: [2, 1], rotate: 90}
//   texture: {checker: {colors: [[1, 1, 1], [0, 0, 0]], size: 0.5}}
//   texture: {marble: {colors: [[0.9, 0.9, 0.85], [0.3, 0.3, 0.35]], scale: 2}}
//
// An image (its path relative to the scene file's folder) lies over the
// shape's texture coordinates (its own, or its object's `mapping`), moved by
// scale, rotate and offset; checker squares alternate in the same
// coordinates; perlin, marble and wood are solid textures of the position.
#pragma once

#include <filesystem>
#include <memory>

#include "io/image_io.hpp"
#include "io/scene_files.hpp"
#include "io/yaml_reader.hpp"
#include "scene/textures/bump_map.hpp"
#include "scene/textures/normal_map.hpp"
#include "scene/textures/texture.hpp"

namespace rise {

// An image's texels are decoded by `encoding`: sRGB for colours, linear for
// data such as a ks texture's factors.
std::shared_ptr<const Texture> readTexture(const Field& field, SceneFiles& files,
                                           Encoding encoding = Encoding::Srgb);

// The `bump` of a material: "bump: {map: <a texture, as above>, strength: 0.05}",
// the height being the map's brightness times strength (scene units; 1 by
// default). A bump map of an image should be filtered bilinearly: nearest
// texels have no slope between them.
std::shared_ptr<const BumpMap> readBump(const Field& field, SceneFiles& files);

// The `normal_map` of a material: "normal_map: {image: path, filter, scale,
// offset, rotate}" as an image texture, its values read linearly (not as
// sRGB colours).
std::shared_ptr<const NormalMap> readNormalMap(const Field& field, SceneFiles& files);

}  // namespace rise
