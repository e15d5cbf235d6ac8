#include "io/mesh_reader.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "core/text.hpp"
#include "io/image_io.hpp"
#include "io/mapping_reader.hpp"
#include "io/mesh_file.hpp"
#include "scene/shapes/keyframed_mesh.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/mesh_mapping.hpp"

namespace rise {

namespace {

// A face of three or more vertex indices becomes the fan of triangles that
// share its first vertex.
void appendFan(const Field& face, int vertexCount, std::vector<std::array<int, 3>>& triangles) {
  std::vector<int> indices;
  for (const Field& index :
       readList(face, "a list of 3 or more vertex indices", "a vertex index of mesh", 3)) {
    indices.push_back(readWholeNumber(index, Bound::NonNegative));
    if (indices.back() >= vertexCount)
      failExpected(index, "an index from 0 to " + std::to_string(vertexCount - 1) +
                              ", as 'vertices' has " + std::to_string(vertexCount) + " points");
  }
  for (std::size_t i = 1; i + 1 < indices.size(); ++i)
    triangles.push_back({indices[0], indices[i], indices[i + 1]});
}

// The poses of a mesh (one, or its keyframes), read in its own space, take
// the object's `mapping` there, so that the texture moves with the mesh, and
// then its transform.
void mapAndPlace(const CheckedMap& mesh, std::span<MeshGeometry> poses,
                 const Mat4& worldFromObject) {
  if (const std::optional<Field> field = mesh.optional("mapping")) {
    if (const std::optional<Mapping> mapping = readMapping(*field)) applyMapping(*mapping, poses);
  }
  for (MeshGeometry& pose : poses) pose = transformed(std::move(pose), worldFromObject);
}

// "mesh: {vertices: [[x, y, z], ...], faces: [[0, 1, 2], ...]}".
std::unique_ptr<Shape> readInlineMesh(const CheckedMap& mesh, int material,
                                      const Mat4& worldFromObject) {
  std::vector<Vec3> vertices =
      readPoints(mesh.required("vertices"), "a list of 3 or more points [x, y, z]", 3);
  const Field faces = mesh.required("faces");
  std::vector<std::array<int, 3>> triangles;
  for (const Field& face : readList(
           faces, "a list of faces, each a list of 3 or more vertex indices", "a face of mesh", 1))
    appendFan(face, static_cast<int>(vertices.size()), triangles);
  std::array poses{MeshGeometry{std::move(vertices), {}, {}, std::move(triangles)}};
  mapAndPlace(mesh, poses, worldFromObject);
  return std::make_unique<TriangleMesh>(std::move(poses[0]), material);
}

void checkKeyframesExist(const std::vector<Field>& fields, const std::vector<int>& keyframes,
                         int keyframeCount, const std::string& fileName) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (keyframes[i] >= keyframeCount)
      failExpected(fields[i], "a keyframe from 0 to " + std::to_string(keyframeCount - 1) +
                                  ", as " + inQuotes(fileName) + " has " +
                                  std::to_string(keyframeCount));
  }
}

// "mesh: {file: models/x.obj}": a model file, found from the scene file's
// folder. An MD2 model takes the pose of one keyframe, "frame: 40" (the first
// by default), or moves through the keyframes from one to another over the
// scene's time, "frames: [40, 45]": while the shutter is open, or over the
// frames of an animation.
std::unique_ptr<Shape> readMeshFile(const CheckedMap& mesh, const Field& file, int material,
                                    const Mat4& worldFromObject, SceneFiles& files) {
  const std::string fileName = readName(file);
  const std::filesystem::path path = files.path(fileName);
  const std::optional<Field> frame = mesh.optional("frame");
  const std::optional<Field> frames = mesh.optional("frames");
  if (frame && frames)
    failAt(frames->mark, "mesh has both 'frame' and 'frames'; expected one of them");
  std::vector<Field> keyframeFields;
  if (frame) keyframeFields.push_back(*frame);
  if (frames)
    keyframeFields = readList(*frames, "a list of 2 keyframes [first, second]",
                              "a keyframe of 'frames' in mesh", 2, 2);
  if (const std::optional<Field>& posing = frame ? frame : frames; posing && !isMd2File(path))
    failAt(posing->mark, posing->name + " picks keyframes of an MD2 model; " + inQuotes(fileName) +
                             " is not an MD2 file");
  std::vector<int> keyframes;
  for (const Field& field : keyframeFields)
    keyframes.push_back(readWholeNumber(field, Bound::NonNegative));

  try {
    if (!keyframes.empty())
      checkKeyframesExist(keyframeFields, keyframes, md2KeyframeCount(path), fileName);
    // From a keyframe to itself is to stand still in it.
    if (keyframes.size() == 2 && keyframes[0] != keyframes[1]) {
      std::vector<MeshGeometry> poses = loadMd2Keyframes(path, keyframes[0], keyframes[1]);
      mapAndPlace(mesh, poses, worldFromObject);
      return std::make_unique<KeyframedMesh>(std::move(poses), material);
    }
    std::array poses{loadMeshFile(path, keyframes.empty() ? 0 : keyframes[0])};
    mapAndPlace(mesh, poses, worldFromObject);
    return std::make_unique<TriangleMesh>(std::move(poses[0]), material);
  } catch (const MeshFileError& error) {
    failAt(file.mark, "cannot load mesh " + inQuotes(fileName) + ": " + error.what());
  }
}

// The file's material as one of the scene's, added the first time a mesh
// wears it.
int wornMaterial(const std::optional<ModelMaterial>& model, const Field& file,
                 SceneMaterials& materials, SceneFiles& files) {
  const std::string fileName = readName(file);
  Material material = model ? asSceneMaterial(*model) : Material{};
  material.name = (model ? model->name : std::string("default")) + " of " + fileName;
  if (const std::optional<int> worn = materials.find(material.name)) return *worn;
  if (model && model->diffuseTexture) {
    // Files written on Windows separate folders with backslashes.
    std::string texture = model->diffuseTexture->string();
    std::replace(texture.begin(), texture.end(), '\\', '/');
    std::vector<std::string> warnings;
    try {
      material.texture = files.imageTexture(files.path(fileName).parent_path() / texture,
                                            Encoding::Srgb, TextureFilter::Bilinear, warnings);
    } catch (const ImageFileError& error) {
      failAt(file.mark, "cannot load the texture " + inQuotes(texture) + " of material " +
                            inQuotes(model->name) + " of mesh " + inQuotes(fileName) + ": " +
                            error.what());
    }
    files.warn(file.mark, warnings);
  }
  return materials.add(std::move(material));
}

}  // namespace

std::vector<std::unique_ptr<Shape>> readMeshInItsMaterials(const CheckedMap& mesh,
                                                           const Mat4& worldFromObject,
                                                           SceneMaterials& materials,
                                                           SceneFiles& files) {
  const Field file = mesh.required("file");
  const std::string fileName = readName(file);
  for (const std::string_view key : {"frame", "frames"}) {
    if (const std::optional<Field> field = mesh.optional(key))
      failAt(field->mark, field->name +
                              " picks keyframes of an MD2 model, which wears the object's "
                              "'material' and its skin; expected a 'material' beside it");
  }
  std::vector<ModelPart> parts;
  try {
    parts = loadModelParts(files.path(fileName));
  } catch (const MeshFileError& error) {
    failAt(file.mark, "cannot load mesh " + inQuotes(fileName) + ": " + error.what());
  }
  if (std::none_of(parts.begin(), parts.end(), [](const ModelPart& part) { return part.material; }))
    failAt(mesh.mark(), "mesh " + inQuotes(fileName) +
                            " needs a 'material': the file describes none of its own (an OBJ "
                            "file's materials are in the MTL file its 'mtllib' line names)");
  std::vector<std::unique_ptr<Shape>> shapes;
  for (ModelPart& part : parts) {
    std::array poses{std::move(part.geometry)};
    mapAndPlace(mesh, poses, worldFromObject);
    shapes.push_back(std::make_unique<TriangleMesh>(
        std::move(poses[0]), wornMaterial(part.material, file, materials, files)));
  }
  return shapes;
}

std::unique_ptr<Shape> readMesh(const CheckedMap& mesh, int material, const Mat4& worldFromObject,
                                SceneFiles& files) {
  const std::optional<Field> file = mesh.optional("file");
  const std::optional<Field> vertices = mesh.optional("vertices");
  const std::optional<Field> faces = mesh.optional("faces");
  if (file && (vertices || faces))
    failAt(file->mark, std::string("mesh has both 'file' and '") +
                           (vertices ? "vertices" : "faces") +
                           "'; expected either a model 'file' or 'vertices' and 'faces'");
  if (file) return readMeshFile(mesh, *file, material, worldFromObject, files);
  if (!vertices && !faces)
    failAt(mesh.mark(), "mesh needs either 'file' or 'vertices' and 'faces'");
  for (const std::string_view key : {"frame", "frames"}) {
    if (const std::optional<Field> field = mesh.optional(key))
      failAt(field->mark, field->name +
                              " picks keyframes of an MD2 model; expected it with a "
                              "'file', not with 'vertices' and 'faces'");
  }
  return readInlineMesh(mesh, material, worldFromObject);
}

int withMd2Skin(const CheckedMap& mesh, int material, SceneMaterials& materials,
                SceneFiles& files) {
  const std::optional<Field> file = mesh.optional("file");
  if (!file || materials[material].texture) return material;
  const std::filesystem::path model = files.path(readName(*file));
  if (!isMd2File(model)) return material;
  const std::optional<std::filesystem::path> skin = findMd2Skin(model);
  if (!skin) return material;
  const std::string name = materials[material].name + " with " + skin->filename().string();
  if (const std::optional<int> worn = materials.find(name)) return *worn;
  Material skinned = materials[material];
  skinned.name = name;
  std::vector<std::string> warnings;
  try {
    skinned.texture = files.imageTexture(*skin, Encoding::Srgb, TextureFilter::Bilinear, warnings);
  } catch (const ImageFileError& error) {
    failAt(file->mark,
           "cannot load the skin of mesh " + inQuotes(readName(*file)) + ": " + error.what());
  }
  files.warn(file->mark, warnings);
  return materials.add(std::move(skinned));
}

}  // namespace rise
