#include "scene/scene_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/image_io.hpp"
#include "scene/image_texture.hpp"
#include "scene/mapping_reader.hpp"
#include "scene/mesh_file.hpp"
#include "scene/mesh_mapping.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/keyframed_mesh.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/moving_shape.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "scene/texture_reader.hpp"
#include "scene/transform.hpp"
#include "scene/yaml_reader.hpp"

namespace rise {

namespace {

// How close to parallel the view direction and the up vector may be (the
// sine of the angle between them) before the camera has no defined "right".
constexpr float kParallelSine = 1e-6f;

// How close to a line three triangle corners may be (the sine of the angle
// between two edges) before the triangle has no area to hit.
constexpr float kCollinearSine = 1e-6f;

// Reads `key` into `value` when the map has it, keeping the default otherwise.
template <typename T, typename Read>
void readIfPresent(const CheckedMap& map, std::string_view key, T& value, Read read) {
  if (const std::optional<Field> field = map.optional(key)) value = read(*field);
}

float readNonNegative(const Field& field) { return readNumber(field, Bound::NonNegative); }
float readPositive(const Field& field) { return readNumber(field, Bound::Positive); }
int readPositiveWholeNumber(const Field& field) { return readWholeNumber(field, Bound::Positive); }

// One of a fixed set of names, with a suggestion for a misspelt one.
template <typename Choice>
Choice readChoice(const Field& field, const std::vector<std::pair<std::string, Choice>>& choices) {
  const std::string name = readName(field);
  std::vector<std::string> names;
  for (const auto& [choiceName, choice] : choices) {
    if (choiceName == name) return choice;
    names.push_back(choiceName);
  }
  failAt(field.mark, field.name + " is '" + name + "'; " + suggestAlternative(name, names));
}

SamplePattern readPattern(const Field& field) {
  return readChoice<SamplePattern>(field, {{"none", SamplePattern::None},
                                           {"regular", SamplePattern::Regular},
                                           {"jittered", SamplePattern::Jittered},
                                           {"random", SamplePattern::Random},
                                           {"adaptive", SamplePattern::Adaptive}});
}

FilterKind readFilter(const Field& field) {
  return readChoice<FilterKind>(
      field,
      {{"box", FilterKind::Box}, {"tent", FilterKind::Tent}, {"gaussian", FilterKind::Gaussian}});
}

PixelSampling readSampling(const CheckedMap& image, const Field& imageField) {
  const std::optional<Field> samplesField = image.optional("samples");
  const std::optional<Field> patternField = image.optional("pattern");
  std::optional<int> samples;
  std::optional<SamplePattern> pattern;
  if (samplesField) samples = readPositiveWholeNumber(*samplesField);
  if (patternField) pattern = readPattern(*patternField);
  PixelSampling sampling = chooseSampling(PixelSampling{}, samples, pattern);
  readIfPresent(image, "filter", sampling.filter, readFilter);
  readIfPresent(image, "adaptive_threshold", sampling.adaptiveThreshold, readPositive);
  if (const std::string problem = samplingProblem(sampling); !problem.empty())
    failAt((samplesField   ? *samplesField
            : patternField ? *patternField
                           : imageField)
               .mark,
           "image has " + problem);
  return sampling;
}

ImageSpec readImage(const Field& field) {
  const CheckedMap image(
      field, "image",
      {"width", "height", "background", "samples", "pattern", "filter", "adaptive_threshold"});
  ImageSpec spec;
  readIfPresent(image, "width", spec.width, readPositiveWholeNumber);
  readIfPresent(image, "height", spec.height, readPositiveWholeNumber);
  readIfPresent(image, "background", spec.background, readColor);
  spec.sampling = readSampling(image, field);
  return spec;
}

void checkUpIsAcrossView(const Camera& camera, const std::optional<Field>& up,
                         const Field& cameraField) {
  const Vec3 view = glm::normalize(camera.lookAt - camera.position);
  if (glm::length(glm::cross(view, glm::normalize(camera.up))) > kParallelSine) return;
  if (up)
    failExpected(*up, "a direction across the view from 'position' to 'look_at', not along it");
  failAt(cameraField.mark,
         "camera looks straight along the default 'up' [0, 1, 0]; expected an 'up' across the "
         "view from 'position' to 'look_at'");
}

Camera readCamera(const Field& field) {
  const CheckedMap map(
      field, "camera",
      {"position", "look_at", "up", "fov", "aperture", "focal_distance", "shutter"});
  Camera camera;
  camera.position = readVec3(map.required("position"));
  const Field lookAt = map.required("look_at");
  camera.lookAt = readVec3(lookAt);
  if (!(glm::length(camera.lookAt - camera.position) > 0.0f))
    failAt(lookAt.mark,
           "'look_at' in camera is the same point as 'position'; expected a point for the camera "
           "to look towards");
  const std::optional<Field> up = map.optional("up");
  if (up) camera.up = readDirection(*up);
  checkUpIsAcrossView(camera, up, field);
  if (const std::optional<Field> fov = map.optional("fov")) {
    camera.fovDegrees = readNumber(*fov);
    if (camera.fovDegrees <= 0.0f || camera.fovDegrees >= 180.0f)
      failExpected(*fov, "an angle in degrees > 0 and < 180");
  }
  readIfPresent(map, "aperture", camera.aperture, readNonNegative);
  readIfPresent(map, "focal_distance", camera.focalDistance, readPositive);
  if (const std::optional<Field> shutter = map.optional("shutter")) {
    const std::vector<Field> times =
        readList(*shutter, "a list of 2 times [open, close]", "a time of 'shutter'", 2, 2);
    camera.shutterOpen = readNumber(times[0]);
    camera.shutterClose = readNumber(times[1]);
    if (camera.shutterClose < camera.shutterOpen)
      failExpected(times[1], "a closing time no earlier than the opening time");
  }
  return camera;
}

// An item of a list that names its kind by its one key, with its properties
// under it: "- sphere: {center: [0, 0, 0], radius: 1}".
MapEntry readKindAndProperties(const Field& item, std::string_view kindWord,
                               const std::vector<std::string>& kinds) {
  const std::string expectation = "a map with one key naming the " + std::string(kindWord) + " (" +
                                  joinedWithCommas(kinds) +
                                  ") and its properties indented under it";
  if (!item.node.IsMap() || item.node.size() != 1) failExpected(item, expectation);
  const MapEntry entry = readMap(item, expectation, item.name).front();
  if (std::find(kinds.begin(), kinds.end(), entry.key) == kinds.end())
    failAt(entry.keyMark, "unknown " + std::string(kindWord) + " '" + entry.key + "'; " +
                              suggestAlternative(entry.key, kinds));
  return entry;
}

Color readLightColor(const CheckedMap& light) {
  Color color(1.0f);
  readIfPresent(light, "color", color, readColor);
  return color;
}

// Each light reader builds its light from its properties.
using LightReader = std::unique_ptr<Light> (*)(const CheckedMap& properties, const Color& color);

struct LightKind {
  std::string name;
  std::vector<std::string> keys;
  LightReader read;
};

const std::vector<LightKind>& lightKinds() {
  static const std::vector<LightKind> kinds{
      {"point",
       {"position"},
       [](const CheckedMap& light, const Color& color) -> std::unique_ptr<Light> {
         return std::make_unique<PointLight>(readVec3(light.required("position")), color);
       }},
      {"directional",
       {"direction"},
       [](const CheckedMap& light, const Color& color) -> std::unique_ptr<Light> {
         return std::make_unique<DirectionalLight>(readDirection(light.required("direction")),
                                                   color);
       }},
      {"rect",
       {"corner", "edge1", "edge2"},
       [](const CheckedMap& light, const Color& color) -> std::unique_ptr<Light> {
         const Vec3 corner = readVec3(light.required("corner"));
         const Vec3 edge1 = readDirection(light.required("edge1"));
         return std::make_unique<RectLight>(corner, edge1, readDirection(light.required("edge2")),
                                            color);
       }},
      {"disk",
       {"center", "normal", "radius"},
       [](const CheckedMap& light, const Color& color) -> std::unique_ptr<Light> {
         const Vec3 center = readVec3(light.required("center"));
         const Vec3 normal = readDirection(light.required("normal"));
         return std::make_unique<DiskLight>(center, normal, readPositive(light.required("radius")),
                                            color);
       }},
      {"sphere",
       {"center", "radius"},
       [](const CheckedMap& light, const Color& color) -> std::unique_ptr<Light> {
         const Vec3 center = readVec3(light.required("center"));
         return std::make_unique<SphereLight>(center, readPositive(light.required("radius")),
                                              color);
       }},
  };
  return kinds;
}

std::unique_ptr<Light> readLight(const Field& item) {
  std::vector<std::string> kindNames;
  for (const LightKind& kind : lightKinds()) kindNames.push_back(kind.name);
  const MapEntry entry = readKindAndProperties(item, "light type", kindNames);
  const LightKind& kind = *std::find_if(lightKinds().begin(), lightKinds().end(),
                                        [&](const LightKind& k) { return k.name == entry.key; });
  const std::string name = entry.key + " light";
  std::vector<std::string> keys = kind.keys;
  keys.push_back("color");
  const CheckedMap light(makeField(entry.value, name, entry.keyMark), name, keys);
  return kind.read(light, readLightColor(light));
}

Material readMaterial(const MapEntry& entry, const std::filesystem::path& sceneDirectory) {
  const std::string name = "material '" + entry.key + "'";
  const CheckedMap map(makeField(entry.value, name, entry.keyMark), name,
                       {"color", "texture", "bump", "normal_map", "ka", "kd", "ks", "ks_texture",
                        "n", "reflection", "transmission", "ior", "roughness"});
  Material material;
  material.name = entry.key;
  readIfPresent(map, "color", material.color, readColor);
  if (const std::optional<Field> texture = map.optional("texture"))
    material.texture = readTexture(*texture, sceneDirectory);
  if (const std::optional<Field> bump = map.optional("bump"))
    material.bump = readBump(*bump, sceneDirectory);
  if (const std::optional<Field> normalMap = map.optional("normal_map"))
    material.normalMap = readNormalMap(*normalMap, sceneDirectory);
  readIfPresent(map, "ka", material.ka, readNonNegative);
  readIfPresent(map, "kd", material.kd, readNonNegative);
  readIfPresent(map, "ks", material.ks, readNonNegative);
  if (const std::optional<Field> ksTexture = map.optional("ks_texture"))
    material.ksTexture = readTexture(*ksTexture, sceneDirectory, Encoding::Linear);
  readIfPresent(map, "n", material.n, readNonNegative);
  readIfPresent(map, "reflection", material.reflection, readNonNegative);
  readIfPresent(map, "transmission", material.transmission, readNonNegative);
  readIfPresent(map, "ior", material.ior, readPositive);
  readIfPresent(map, "roughness", material.roughness, readNonNegative);
  return material;
}

std::vector<Material> readMaterials(const Field& field,
                                    const std::filesystem::path& sceneDirectory) {
  std::vector<Material> materials;
  for (const MapEntry& entry :
       readMap(field, "a map from material names to materials", "'materials'"))
    materials.push_back(readMaterial(entry, sceneDirectory));
  return materials;
}

int readMaterialReference(const Field& field, const std::vector<Material>& materials,
                          std::string_view shapeName) {
  const std::string name = readName(field);
  std::vector<std::string> names;
  for (const Material& material : materials) names.push_back(material.name);
  const auto found = std::find(names.begin(), names.end(), name);
  if (found != names.end()) return static_cast<int>(found - names.begin());
  const std::string problem = "undefined material '" + name + "' in " + std::string(shapeName);
  if (names.empty()) failAt(field.mark, problem + "; the scene defines no materials");
  failAt(field.mark, problem + "; " + suggestAlternative(name, names));
}

Vec3 readScale(const Field& field) {
  if (!field.node.IsSequence() && !field.node.IsScalar())
    failExpected(field, "a number or a list of 3 numbers [x, y, z]");
  const Vec3 scale = field.node.IsSequence() ? readVec3(field) : Vec3(readNumber(field));
  if (glm::any(glm::equal(scale, Vec3(0.0f))))
    failExpected(field, "a scale that is not 0 on any axis");
  return scale;
}

// A `transform`, or a `motion`: the placement at the shutter's close, its
// keys changing those of `start`, the placement at the shutter's open.
TransformSpec readPlacement(const Field& field, const std::string& name, TransformSpec start) {
  const CheckedMap map(field, name, {"scale", "rotate", "translate"});
  TransformSpec spec = start;
  readIfPresent(map, "scale", spec.scale, readScale);
  readIfPresent(map, "rotate", spec.rotateDegrees, readVec3);
  readIfPresent(map, "translate", spec.translate, readVec3);
  return spec;
}

// The points of a list, placed in the world.
std::vector<Vec3> readPoints(const Field& field, std::string_view expectation,
                             std::size_t minPoints, std::size_t maxPoints,
                             const Mat4& worldFromObject) {
  std::vector<Vec3> points;
  for (const Field& point :
       readList(field, expectation, "a point of " + field.name, minPoints, maxPoints))
    points.push_back(Vec3(worldFromObject * glm::vec4(readVec3(point), 1.0f)));
  return points;
}

// Each shape reader builds its shape from its properties. Shapes made of
// vertices take the object's transform into them (but for a triangle or
// polygon with a mapping, which it wears in its own space); the others are
// built in their own space and wrapped in a TransformedShape. Files that a
// shape names are found from the scene file's folder.
using ShapeReader = std::unique_ptr<Shape> (*)(const CheckedMap& properties, int material,
                                               const Mat4& worldFromObject,
                                               const std::filesystem::path& sceneDirectory);

std::unique_ptr<Shape> readPlane(const CheckedMap& plane, int material, const Mat4&,
                                 const std::filesystem::path&) {
  const Vec3 point = readVec3(plane.required("point"));
  const Vec3 normal = readDirection(plane.required("normal"));
  return std::make_unique<Plane>(point, normal, material);
}

std::unique_ptr<Shape> readSphere(const CheckedMap& sphere, int material, const Mat4&,
                                  const std::filesystem::path&) {
  const Vec3 center = readVec3(sphere.required("center"));
  const float radius = readPositive(sphere.required("radius"));
  return std::make_unique<Sphere>(center, radius, material);
}

std::unique_ptr<Shape> readBox(const CheckedMap& box, int material, const Mat4&,
                               const std::filesystem::path&) {
  const Field minField = box.required("min");
  const Field maxField = box.required("max");
  const Vec3 min = readVec3(minField);
  const Vec3 max = readVec3(maxField);
  if (!glm::all(glm::greaterThan(max, min)))
    failExpected(maxField,
                 "a corner greater than 'min' " + describe(minField.node) + " in x, y and z");
  return std::make_unique<Box>(min, max, material);
}

// Cylinders and cones: a base point, an axis, a radius and a height.
template <typename AxialShape>
std::unique_ptr<Shape> readAxialShape(const CheckedMap& shape, int material, const Mat4&,
                                      const std::filesystem::path&) {
  const Vec3 base = readVec3(shape.required("base"));
  const Vec3 axis = readDirection(shape.required("axis"));
  const float radius = readPositive(shape.required("radius"));
  const float height = readPositive(shape.required("height"));
  return std::make_unique<AxialShape>(base, axis, radius, height, material);
}

std::unique_ptr<Shape> readTriangle(const CheckedMap& triangle, int material,
                                    const Mat4& worldFromObject, const std::filesystem::path&) {
  const Field field = triangle.required("vertices");
  const std::vector<Vec3> v =
      readPoints(field, "a list of 3 points [x, y, z]", 3, 3, worldFromObject);
  const Vec3 edge1 = v[1] - v[0];
  const Vec3 edge2 = v[2] - v[0];
  if (glm::length(glm::cross(edge1, edge2)) <=
      kCollinearSine * glm::length(edge1) * glm::length(edge2))
    failAt(field.mark, field.name + " lie on one line; expected the corners of a triangle");
  return std::make_unique<Triangle>(std::array<Vec3, 3>{v[0], v[1], v[2]}, material);
}

std::unique_ptr<Shape> readPolygon(const CheckedMap& polygon, int material,
                                   const Mat4& worldFromObject, const std::filesystem::path&) {
  const Field field = polygon.required("vertices");
  std::vector<Vec3> vertices =
      readPoints(field, "a list of 3 or more points [x, y, z]", 3, SIZE_MAX, worldFromObject);
  if (!isPlanarConvexPolygon(vertices))
    failAt(field.mark, field.name +
                           " are not the corners of a flat convex polygon; expected points in "
                           "one plane, in order around a convex outline");
  return std::make_unique<ConvexPolygon>(std::move(vertices), material);
}

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

// The poses of a mesh (one, or two keyframes), read in its own space, take
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
  std::vector<Vec3> vertices = readPoints(
      mesh.required("vertices"), "a list of 3 or more points [x, y, z]", 3, SIZE_MAX, Mat4(1.0f));
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
                                  ", as '" + fileName + "' has " + std::to_string(keyframeCount));
  }
}

// "mesh: {file: models/x.obj}": a model file, found from the scene file's
// folder. An MD2 model takes the pose of one keyframe, "frame: 40" (the first
// by default), or moves between two while the shutter is open,
// "frames: [40, 41]".
std::unique_ptr<Shape> readMeshFile(const CheckedMap& mesh, const Field& file, int material,
                                    const Mat4& worldFromObject,
                                    const std::filesystem::path& sceneDirectory) {
  const std::string fileName = readName(file);
  const std::filesystem::path path = sceneDirectory / fileName;
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
    failAt(posing->mark, posing->name + " picks keyframes of an MD2 model; '" + fileName +
                             "' is not an MD2 file");
  std::vector<int> keyframes;
  for (const Field& field : keyframeFields)
    keyframes.push_back(readWholeNumber(field, Bound::NonNegative));

  try {
    if (!keyframes.empty())
      checkKeyframesExist(keyframeFields, keyframes, md2KeyframeCount(path), fileName);
    if (keyframes.size() == 2) {
      auto [start, end] = loadMd2Keyframes(path, keyframes[0], keyframes[1]);
      std::array poses{std::move(start), std::move(end)};
      mapAndPlace(mesh, poses, worldFromObject);
      return std::make_unique<KeyframedMesh>(std::move(poses[0]), std::move(poses[1]), material);
    }
    std::array poses{loadMeshFile(path, keyframes.empty() ? 0 : keyframes[0])};
    mapAndPlace(mesh, poses, worldFromObject);
    return std::make_unique<TriangleMesh>(std::move(poses[0]), material);
  } catch (const MeshFileError& error) {
    failAt(file.mark, "cannot load mesh '" + fileName + "': " + error.what());
  }
}

// A mesh is either read from a model file or written out in the scene.
std::unique_ptr<Shape> readMesh(const CheckedMap& mesh, int material, const Mat4& worldFromObject,
                                const std::filesystem::path& sceneDirectory) {
  const std::optional<Field> file = mesh.optional("file");
  const std::optional<Field> vertices = mesh.optional("vertices");
  const std::optional<Field> faces = mesh.optional("faces");
  if (file && (vertices || faces))
    failAt(file->mark, std::string("mesh has both 'file' and '") +
                           (vertices ? "vertices" : "faces") +
                           "'; expected either a model 'file' or 'vertices' and 'faces'");
  if (file) return readMeshFile(mesh, *file, material, worldFromObject, sceneDirectory);
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

// An MD2 model whose material has no texture wears its skin (findMd2Skin):
// the material again, under the name "<material> with <skin>", with the skin
// as its texture, shared by every model that wears the same skin.
int withMd2Skin(const CheckedMap& mesh, int material, std::vector<Material>& materials,
                const std::filesystem::path& sceneDirectory) {
  const std::optional<Field> file = mesh.optional("file");
  if (!file || materials[material].texture) return material;
  const std::filesystem::path model = sceneDirectory / readName(*file);
  if (!isMd2File(model)) return material;
  const std::optional<std::filesystem::path> skin = findMd2Skin(model);
  if (!skin) return material;
  const std::string name = materials[material].name + " with " + skin->filename().string();
  const auto worn = std::find_if(materials.begin(), materials.end(),
                                 [&](const Material& m) { return m.name == name; });
  if (worn != materials.end()) return static_cast<int>(worn - materials.begin());
  Material skinned = materials[material];
  skinned.name = name;
  try {
    skinned.texture = std::make_shared<ImageTexture>(
        std::make_shared<const Image>(readTextureImage(*skin)), TextureFilter::Bilinear);
  } catch (const ImageFileError& error) {
    failAt(file->mark, "cannot load the skin of mesh '" + readName(*file) + "': " + error.what());
  }
  materials.push_back(std::move(skinned));
  return static_cast<int>(materials.size()) - 1;
}

struct ShapeKind {
  std::string name;
  std::vector<std::string> keys;
  bool takesTransformIntoVertices;
  ShapeReader read;
};

const std::vector<ShapeKind>& shapeKinds() {
  static const std::vector<ShapeKind> kinds{
      {"plane", {"point", "normal"}, false, readPlane},
      {"sphere", {"center", "radius", "mapping"}, false, readSphere},
      {"box", {"min", "max", "mapping"}, false, readBox},
      {"cylinder",
       {"base", "axis", "radius", "height", "mapping"},
       false,
       readAxialShape<Cylinder>},
      {"cone", {"base", "axis", "radius", "height", "mapping"}, false, readAxialShape<Cone>},
      {"triangle", {"vertices", "mapping"}, true, readTriangle},
      {"polygon", {"vertices", "mapping"}, true, readPolygon},
      {"mesh", {"vertices", "faces", "file", "frame", "frames", "mapping"}, true, readMesh},
  };
  return kinds;
}

std::unique_ptr<Shape> readObject(const Field& item, std::vector<Material>& materials,
                                  const std::filesystem::path& sceneDirectory) {
  std::vector<std::string> kindNames;
  for (const ShapeKind& kind : shapeKinds()) kindNames.push_back(kind.name);
  const MapEntry entry = readKindAndProperties(item, "shape", kindNames);
  const ShapeKind& kind = *std::find_if(shapeKinds().begin(), shapeKinds().end(),
                                        [&](const ShapeKind& k) { return k.name == entry.key; });

  std::vector<std::string> keys = kind.keys;
  keys.insert(keys.end(), {"material", "transform", "motion"});
  const CheckedMap properties(makeField(entry.value, kind.name, entry.keyMark), kind.name, keys);
  int material = readMaterialReference(properties.required("material"), materials, kind.name);
  if (kind.name == "mesh") material = withMd2Skin(properties, material, materials, sceneDirectory);
  TransformSpec transform;
  if (const std::optional<Field> field = properties.optional("transform"))
    transform = readPlacement(*field, "the transform of " + kind.name, TransformSpec{});
  // A mesh takes its mapping into its vertices as it loads (mapAndPlace);
  // another shape wears it in its own space, inside its placement.
  std::optional<Mapping> mapping;
  if (const std::optional<Field> field = properties.optional("mapping");
      field && kind.name != "mesh")
    mapping = readMapping(*field);
  const auto readInOwnSpace = [&] {
    std::unique_ptr<Shape> shape = kind.read(properties, material, Mat4(1.0f), sceneDirectory);
    if (!mapping) return shape;
    return std::unique_ptr<Shape>(std::make_unique<MappedShape>(std::move(shape), *mapping));
  };
  if (const std::optional<Field> field = properties.optional("motion")) {
    const TransformSpec close = readPlacement(*field, "the motion of " + kind.name, transform);
    return std::make_unique<MovingShape>(readInOwnSpace(), transform, close);
  }

  const Mat4 toWorld = worldFromObject(transform);
  if (kind.takesTransformIntoVertices && !mapping)
    return kind.read(properties, material, toWorld, sceneDirectory);
  std::unique_ptr<Shape> shape = readInOwnSpace();
  if (transform.isIdentity()) return shape;
  return std::make_unique<TransformedShape>(std::move(shape), toWorld);
}

Scene readScene(const YAML::Node& root, std::string source) {
  const CheckedMap map(Field{root, "the scene", root.Mark()}, "the scene",
                       {"image", "camera", "ambient", "lights", "materials", "objects"});
  Scene scene;
  scene.source = std::move(source);
  readIfPresent(map, "image", scene.image, readImage);
  scene.camera = readCamera(map.required("camera"));
  readIfPresent(map, "ambient", scene.ambient, readColor);
  if (const std::optional<Field> lights = map.optional("lights")) {
    for (const Field& item : readList(*lights, "a list of lights", "an item of 'lights'"))
      scene.lights.push_back(readLight(item));
  }
  const std::filesystem::path sceneDirectory = std::filesystem::path(scene.source).parent_path();
  if (const std::optional<Field> materials = map.optional("materials"))
    scene.materials = readMaterials(*materials, sceneDirectory);
  for (const Field& item :
       readList(map.required("objects"), "a list of objects", "an item of 'objects'"))
    scene.shapes.push_back(readObject(item, scene.materials, sceneDirectory));
  return scene;
}

// yaml-cpp's wording for the syntax errors people make most, said plainly.
std::string explainSyntaxError(const YAML::ParserException& error, std::string_view text) {
  if (error.msg == YAML::ErrorMsg::END_OF_SEQ_FLOW)
    return "a list opened with '[' is not closed with ']'";
  if (error.msg == YAML::ErrorMsg::END_OF_MAP_FLOW)
    return "a map opened with '{' is not closed with '}'";
  if (error.msg == YAML::ErrorMsg::FLOW_END && error.mark.pos >= 0 &&
      static_cast<std::size_t>(error.mark.pos) < text.size())
    return std::string("unexpected '") + text[error.mark.pos] +
           "'; check that the brackets before it are closed in order";
  if (error.msg == YAML::ErrorMsg::MAP_VALUE)
    return "unexpected ':' (wrong indentation, a tab, or a value with ': ' that needs quotes?)";
  if (error.msg == YAML::ErrorMsg::TAB_IN_INDENTATION)
    return "a tab in the indentation; YAML indents with spaces";
  return error.msg;
}

SceneError errorAt(const std::string& source, const YAML::Mark& mark, const std::string& message) {
  return SceneError(source, mark.line + 1, mark.column + 1, message);
}

}  // namespace

Scene loadScene(std::string_view text, std::string sourceName) {
  try {
    const std::vector<YAML::Node> documents = YAML::LoadAll(std::string(text));
    if (documents.empty() || documents[0].IsNull())
      throw SceneError(sourceName,
                       "the scene file is empty; expected at least 'camera' and 'objects'");
    // An empty document after the scene, as an editor may leave after a
    // final '---', says nothing and is harmless.
    const auto second = std::find_if(documents.begin() + 1, documents.end(),
                                     [](const YAML::Node& document) { return !document.IsNull(); });
    if (second != documents.end())
      failAt(second->Mark(),
             "a second YAML document (after '---'); expected the scene file to hold one scene");
    return readScene(documents[0], sourceName);
  } catch (const YAML::ParserException& error) {
    throw errorAt(sourceName, error.mark, "invalid YAML: " + explainSyntaxError(error, text));
  } catch (const YamlValueError& error) {
    throw errorAt(sourceName, error.mark(), error.what());
  }
}

Scene loadSceneFile(const std::filesystem::path& path) {
  // A directory opens as a file stream on POSIX systems and only fails when read.
  if (std::filesystem::is_directory(path))
    throw SceneError(path.string(), "cannot open the scene file (" +
                                        std::make_error_code(std::errc::is_a_directory).message() +
                                        ")");
  errno = 0;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    const std::string cause =
        errno != 0 ? std::generic_category().message(errno) : "unknown reason";
    throw SceneError(path.string(), "cannot open the scene file (" + cause + ")");
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw SceneError(path.string(), "cannot read the scene file");
  return loadScene(text.str(), path.string());
}

}  // namespace rise
