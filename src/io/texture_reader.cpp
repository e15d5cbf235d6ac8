#include "io/texture_reader.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/text.hpp"
#include "io/image_io.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/noise_texture.hpp"
#include "scene/textures/transformed_texture.hpp"

namespace rise {

namespace {

const std::vector<std::pair<std::string, NoisePattern>> kNoisePatterns{
    {"perlin", NoisePattern::Perlin},
    {"marble", NoisePattern::Marble},
    {"wood", NoisePattern::Wood}};

// A number for both coordinates, or a pair [u, v].
Vec2 readPair(const Field& field) {
  if (!field.node.isSequence()) return Vec2(readNumber(field));
  const std::vector<Field> items = readList(field, "a number or a list of 2 numbers [u, v]",
                                            "a coordinate of " + field.name, 2, 2);
  return {readNumber(items[0]), readNumber(items[1])};
}

std::pair<Color, Color> readTwoColors(const CheckedMap& map, const std::string& what) {
  const std::vector<Field> colors =
      readList(map.required("colors"), "a list of 2 colours", "a colour of the " + what, 2, 2);
  return {readColor(colors[0]), readColor(colors[1])};
}

TextureFilter readTextureFilter(const Field& field) {
  return readChoice<TextureFilter>(field, {{"nearest", TextureFilter::Nearest},
                                           {"bilinear", TextureFilter::Bilinear},
                                           {"trilinear", TextureFilter::Trilinear},
                                           {"summed-area", TextureFilter::SummedArea},
                                           {"elliptical", TextureFilter::EllipticalAverage}});
}

std::shared_ptr<const Texture> readImageTexture(const CheckedMap& map, const Field& image,
                                                SceneFiles& files, Encoding encoding) {
  const std::string fileName = readName(image);
  TextureFilter filter = TextureFilter::Bilinear;
  if (const std::optional<Field> field = map.optional("filter")) filter = readTextureFilter(*field);
  UvTransform transform;
  if (const std::optional<Field> field = map.optional("scale")) transform.scale = readPair(*field);
  if (const std::optional<Field> field = map.optional("offset"))
    transform.offset = readPair(*field);
  if (const std::optional<Field> field = map.optional("rotate"))
    transform.rotateDegrees = readNumber(*field);
  std::shared_ptr<const Texture> texture;
  std::vector<std::string> warnings;
  try {
    texture = files.imageTexture(files.path(fileName), encoding, filter, warnings);
  } catch (const ImageFileError& error) {
    failAt(image.mark, "cannot load texture image " + inQuotes(fileName) + ": " + error.what());
  }
  files.warn(image.mark, warnings);
  if (transform.isIdentity()) return texture;
  return std::make_shared<TransformedTexture>(std::move(texture), transform);
}

std::shared_ptr<const Texture> readChecker(const Field& field) {
  const CheckedMap checker(field, "checker texture", {"colors", "size"});
  const auto [even, odd] = readTwoColors(checker, "checker");
  float size = 1.0f;
  if (const std::optional<Field> sizeField = checker.optional("size"))
    size = readNumber(*sizeField, Bound::Positive);
  return std::make_shared<CheckerTexture>(even, odd, size);
}

std::shared_ptr<const Texture> readNoise(const Field& field, NoisePattern pattern) {
  const CheckedMap noise(field, field.name, {"colors", "scale"});
  const auto [first, second] = readTwoColors(noise, field.name);
  float scale = 1.0f;
  if (const std::optional<Field> scaleField = noise.optional("scale"))
    scale = readNumber(*scaleField, Bound::Positive);
  return std::make_shared<NoiseTexture>(pattern, first, second, scale);
}

// The texture-coordinate distance of a bump map's differences: well under a
// texel of any image in use, where a bilinear texture is linear, so that the
// differences give its exact slope.
constexpr float kBumpStep = 1.0f / 8192.0f;

}  // namespace

std::shared_ptr<const NormalMap> readNormalMap(const Field& field, SceneFiles& files) {
  const CheckedMap map(field, "normal map", {"image", "filter", "scale", "offset", "rotate"});
  return std::make_shared<NormalMap>(
      readImageTexture(map, map.required("image"), files, Encoding::Linear));
}

std::shared_ptr<const BumpMap> readBump(const Field& field, SceneFiles& files) {
  const CheckedMap bump(field, "bump", {"map", "strength"});
  std::shared_ptr<const Texture> map = readTexture(bump.required("map"), files);
  float strength = 1.0f;
  if (const std::optional<Field> strengthField = bump.optional("strength"))
    strength = readNumber(*strengthField);
  return std::make_shared<BumpMap>(std::move(map), strength, Vec2(kBumpStep));
}

std::shared_ptr<const Texture> readTexture(const Field& field, SceneFiles& files,
                                           Encoding encoding) {
  std::vector<std::string> kinds{"image", "checker"};
  for (const auto& [name, pattern] : kNoisePatterns) kinds.push_back(name);
  std::vector<std::string> keys = kinds;
  keys.insert(keys.end(), {"filter", "scale", "offset", "rotate"});
  const CheckedMap map(field, "texture", keys);
  std::vector<Field> given;
  std::vector<std::string> givenKinds;
  for (const std::string& kind : kinds) {
    if (const std::optional<Field> value = map.optional(kind)) {
      given.push_back(*value);
      givenKinds.push_back(kind);
    }
  }
  if (given.size() != 1)
    failAt(map.mark(), "texture needs exactly one of " + joined(kinds) + "; got " +
                           (given.empty() ? "none" : joined(givenKinds)));
  if (givenKinds[0] == "image") return readImageTexture(map, given[0], files, encoding);
  for (const std::string_view key : {"filter", "scale", "offset", "rotate"}) {
    if (const std::optional<Field> misplaced = map.optional(key))
      failAt(misplaced->mark,
             misplaced->name + " belongs to an image texture, not to " + givenKinds[0]);
  }
  if (givenKinds[0] == "checker") return readChecker(given[0]);
  const auto noise = std::find_if(kNoisePatterns.begin(), kNoisePatterns.end(),
                                  [&](const auto& entry) { return entry.first == givenKinds[0]; });
  return readNoise(given[0], noise->second);
}

}  // namespace rise
