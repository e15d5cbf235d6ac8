#include "io/scene_file.hpp"

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/text.hpp"
#include "io/file_limits.hpp"
#include "io/image_io.hpp"
#include "io/shape_reader.hpp"
#include "io/texture_reader.hpp"
#include "io/yaml_reader.hpp"

namespace rise {

namespace {

// How close to parallel the view direction and the up vector may be (the
// sine of the angle between them) before the camera has no defined "right".
constexpr float kParallelSine = 1e-6f;
// Beyond this distance from what it looks at, a camera's rays square numbers
// that floats cannot hold.
constexpr double kFarthestCamera = 1e15;
constexpr float kLeastIor = 0.1f;
constexpr float kGreatestIor = 10.0f;
constexpr float kGreatestRoughness = 10.0f;  // a cone of 84 degrees

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
  const auto side = [](const Field& field) {
    const int pixels = readPositiveWholeNumber(field);
    if (pixels > kLargestImageSide)
      failExpected(field,
                   "a whole number of pixels from 1 to " + std::to_string(kLargestImageSide));
    return pixels;
  };
  readIfPresent(image, "width", spec.width, side);
  readIfPresent(image, "height", spec.height, side);
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

// Where an animation's camera ends: "motion: {position: ..., look_at: ...}",
// each key changing the camera's own.
Camera::Placement readCameraMotion(const Field& field, const Camera& start) {
  const CheckedMap map(field, "the motion of the camera", {"position", "look_at", "up"});
  Camera end = start;
  readIfPresent(map, "position", end.position, readVec3);
  readIfPresent(map, "look_at", end.lookAt, readVec3);
  if (const std::optional<Field> up = map.optional("up")) end.up = readDirection(*up);
  if (!(glm::length(end.lookAt - end.position) > 0.0f))
    failAt(field.mark,
           "the camera's motion ends looking at the point it stands on; expected "
           "'look_at' apart from 'position'");
  checkUpIsAcrossView(end, map.optional("up"), field);
  return {end.position, end.lookAt, end.up};
}

Camera readCamera(const Field& field) {
  const CheckedMap map(
      field, "camera",
      {"position", "look_at", "up", "fov", "aperture", "focal_distance", "shutter", "motion"});
  Camera camera;
  camera.position = readVec3(map.required("position"));
  const Field lookAt = map.required("look_at");
  camera.lookAt = readVec3(lookAt);
  if (!(glm::length(camera.lookAt - camera.position) > 0.0f))
    failAt(lookAt.mark,
           "'look_at' in camera is the same point as 'position'; expected a point for the camera "
           "to look towards");
  const double distance = glm::length(glm::dvec3(camera.lookAt) - glm::dvec3(camera.position));
  if (distance > kFarthestCamera)
    failAt(lookAt.mark, "'look_at' in camera is " + shortNumber(distance) +
                            " units from 'position'; expected a camera at most " +
                            shortNumber(kFarthestCamera) + " units from the point it looks at");
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
  if (const std::optional<Field> motion = map.optional("motion"))
    camera.endPlacement = readCameraMotion(*motion, camera);
  return camera;
}

// An animation: "animation: {frames: 40}" cuts the scene's time into frames.
int readAnimationFrames(const Field& field) {
  const CheckedMap map(field, "animation", {"frames"});
  return readWholeNumber(map.required("frames"), Bound::Positive);
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
         const Vec3 edge1 = readNonZeroVector(light.required("edge1"));
         return std::make_unique<RectLight>(corner, edge1,
                                            readNonZeroVector(light.required("edge2")), color);
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

Material readMaterial(const MapEntry& entry, SceneFiles& files) {
  const std::string name = "material " + inQuotes(entry.key);
  const CheckedMap map(makeField(entry.value, name, entry.keyMark), name,
                       {"color", "texture", "bump", "normal_map", "ka", "kd", "ks", "ks_texture",
                        "n", "reflection", "transmission", "ior", "roughness", "emission"});
  Material material;
  material.name = entry.key;
  readIfPresent(map, "color", material.color, readColor);
  if (const std::optional<Field> texture = map.optional("texture"))
    material.texture = readTexture(*texture, files);
  if (const std::optional<Field> bump = map.optional("bump"))
    material.bump = readBump(*bump, files);
  if (const std::optional<Field> normalMap = map.optional("normal_map"))
    material.normalMap = readNormalMap(*normalMap, files);
  readIfPresent(map, "ka", material.ka, readNonNegative);
  readIfPresent(map, "kd", material.kd, readNonNegative);
  readIfPresent(map, "ks", material.ks, readNonNegative);
  if (const std::optional<Field> ksTexture = map.optional("ks_texture"))
    material.ksTexture = readTexture(*ksTexture, files, Encoding::Linear);
  readIfPresent(map, "n", material.n, readNonNegative);
  // Each ray's weight is a fraction of light; an index of refraction or a
  // cone beyond these makes directions that floats cannot hold.
  const auto fraction = [](const Field& field) { return readNumberFrom(field, 0.0f, 1.0f); };
  readIfPresent(map, "reflection", material.reflection, fraction);
  readIfPresent(map, "transmission", material.transmission, fraction);
  readIfPresent(map, "ior", material.ior,
                [](const Field& field) { return readNumberFrom(field, kLeastIor, kGreatestIor); });
  readIfPresent(map, "roughness", material.roughness,
                [](const Field& field) { return readNumberFrom(field, 0.0f, kGreatestRoughness); });
  readIfPresent(map, "emission", material.emission, readColor);
  return material;
}

std::vector<Material> readMaterials(const Field& field, SceneFiles& files) {
  std::vector<Material> materials;
  for (const MapEntry& entry :
       readMap(field, "a map from material names to materials", "'materials'"))
    materials.push_back(readMaterial(entry, files));
  return materials;
}

Scene readScene(const YamlNode& root, std::string source) {
  const CheckedMap map(
      Field{root, "the scene", root.mark()}, "the scene",
      {"image", "camera", "ambient", "lights", "materials", "objects", "animation"});
  Scene scene;
  scene.source = std::move(source);
  readIfPresent(map, "image", scene.image, readImage);
  scene.camera = readCamera(map.required("camera"));
  readIfPresent(map, "animation", scene.animationFrames, readAnimationFrames);
  readIfPresent(map, "ambient", scene.ambient, readColor);
  if (const std::optional<Field> lights = map.optional("lights")) {
    for (const Field& item : readList(*lights, "a list of lights", "an item of 'lights'"))
      scene.lights.push_back(readLight(item));
  }
  SceneFiles files(std::filesystem::path(scene.source).parent_path());
  if (const std::optional<Field> materials = map.optional("materials"))
    scene.materials = readMaterials(*materials, files);
  SceneMaterials materials(scene.materials);
  int object = 0;
  for (const Field& item :
       readList(map.required("objects"), "a list of objects", "an item of 'objects'")) {
    std::vector<std::unique_ptr<Shape>> shapes = readObject(item, materials, files);
    for (std::unique_ptr<Shape>& shape : shapes) {
      std::string name = describeObject(item);
      // A model in its own materials is a mesh for each of them.
      if (shapes.size() > 1) name += " wearing " + materials[shape->material()].name;
      scene.shapeNames.push_back(std::move(name));
      scene.shapeObjects.push_back(object);
      scene.shapes.push_back(std::move(shape));
    }
    ++object;
  }
  for (const SceneFiles::Warning& warning : files.warnings())
    scene.warnings.push_back(scene.source + ":" + std::to_string(warning.mark.line + 1) + ":" +
                             std::to_string(warning.mark.column + 1) +
                             ": warning: " + warning.message);
  return scene;
}

SceneError errorAt(const std::string& source, Mark mark, const std::string& message) {
  return SceneError(source, mark.line + 1, mark.column + 1, message);
}

}  // namespace

Scene loadScene(std::string_view text, std::string sourceName) {
  try {
    const std::vector<YamlNode> documents = parseYamlDocuments(text);
    if (documents.empty() || documents[0].isNull())
      throw SceneError(sourceName,
                       "the scene file is empty; expected at least 'camera' and 'objects'");
    // An empty document after the scene, as an editor may leave after a
    // final '---', says nothing and is harmless.
    const auto second = std::find_if(documents.begin() + 1, documents.end(),
                                     [](const YamlNode& document) { return !document.isNull(); });
    if (second != documents.end())
      failAt(second->mark(),
             "a second YAML document (after '---'); expected the scene file to hold one scene");
    return readScene(documents[0], sourceName);
  } catch (const YamlError& error) {
    throw errorAt(sourceName, error.mark(), error.what());
  } catch (const YamlValueError& error) {
    throw errorAt(sourceName, error.mark(), error.what());
  }
}

Scene loadSceneStream(std::istream& in, std::string sourceName) {
  const std::optional<std::string> text = readAtMost(in, kLargestSceneFile);
  if (in.bad()) throw SceneError(sourceName, "cannot read the scene file");
  if (!text)
    throw SceneError(sourceName, "the scene file is larger than the " +
                                     megabytes(kLargestSceneFile) +
                                     " that RISE reads; expected a scene, with large meshes in "
                                     "model files (mesh: {file})");
  return loadScene(*text, std::move(sourceName));
}

Scene loadSceneFile(const std::filesystem::path& path) {
  if (const std::optional<std::string> problem = fileKindOrSizeProblem(path, kLargestSceneFile))
    throw SceneError(path.string(), *problem);
  errno = 0;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    const std::string cause =
        errno != 0 ? std::generic_category().message(errno) : "unknown reason";
    throw SceneError(path.string(), "cannot open the scene file (" + cause + ")");
  }
  return loadSceneStream(file, path.string());
}

}  // namespace rise
