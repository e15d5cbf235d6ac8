// The scene file loader: the example scenes load with the values written in
// them, defaults fill what is left out, transforms place shapes, and every bad
// file in tests/scenes/bad is rejected with its exact message. Those messages
// are what users read, so the expected strings below are their specification.
#include "io/scene_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>

#include "support/shape_testing.hpp"

namespace rise {
namespace {

using shape_testing::hitsAt;
using shape_testing::intersect;
using shape_testing::misses;

const std::filesystem::path kSourceDir = RISE_SOURCE_DIR;
const std::filesystem::path kBadScenes = kSourceDir / "tests/scenes/bad";

const Ray kAlongZ{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};

Ray alongZFrom(float x, float y) { return Ray{{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}}; }

// The message loading `text` fails with, or "" when it loads.
std::string errorLoading(std::string_view text) {
  try {
    loadScene(text, "test.yaml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(SceneFile, LoadsTheClassicScene) {
  const Scene scene = loadSceneFile(kSourceDir / "examples/classic.yaml");

  EXPECT_EQ(scene.source, (kSourceDir / "examples/classic.yaml").string());
  EXPECT_EQ(scene.image.width, 640);
  EXPECT_EQ(scene.image.height, 480);
  EXPECT_EQ(scene.image.background, Color(0.05f, 0.05f, 0.1f));
  EXPECT_EQ(scene.camera.position, Vec3(0.0f, 1.5f, -6.0f));
  EXPECT_EQ(scene.camera.lookAt, Vec3(0.0f, 0.8f, 0.0f));
  EXPECT_EQ(scene.camera.fovDegrees, 50.0f);
  EXPECT_EQ(scene.ambient, Color(0.1f));

  ASSERT_EQ(scene.lights.size(), 2u);
  const auto* point = dynamic_cast<const PointLight*>(scene.lights[0].get());
  ASSERT_NE(point, nullptr);
  EXPECT_EQ(point->position(), Vec3(-4.0f, 6.0f, -4.0f));
  const auto* directional = dynamic_cast<const DirectionalLight*>(scene.lights[1].get());
  ASSERT_NE(directional, nullptr);
  EXPECT_EQ(directional->color(), Color(0.3f));

  ASSERT_EQ(scene.materials.size(), 4u);
  EXPECT_EQ(scene.materials[0].name, "red");
  EXPECT_EQ(scene.materials[0].n, 32.0f);
  EXPECT_EQ(scene.materials[1].name, "mirror");
  EXPECT_EQ(scene.materials[1].reflection, 0.8f);
  EXPECT_EQ(scene.materials[2].name, "glass");
  EXPECT_EQ(scene.materials[2].transmission, 0.9f);
  EXPECT_EQ(scene.materials[2].ior, 1.5f);

  ASSERT_EQ(scene.shapes.size(), 9u);
  EXPECT_EQ(scene.materialOf(*scene.shapes[0]).name, "floor");
  EXPECT_EQ(scene.materialOf(*scene.shapes[1]).name, "glass");
  EXPECT_EQ(scene.materialOf(*scene.shapes[8]).name, "red");
  // The glass sphere of radius 1 around (0, 1, 0), seen along z from the camera's height.
  EXPECT_TRUE(hitsAt(intersect(*scene.shapes[1], Ray{{0.0f, 1.0f, -6.0f}, {0.0f, 0.0f, 1.0f}}),
                     5.0f, {0.0f, 1.0f, -1.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(SceneFile, LoadsJson) {
  const Scene scene = loadScene(R"({
    "image": {"width": 320, "height": 200},
    "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 40},
    "lights": [{"point": {"position": [1, 2, 3]}}],
    "materials": {"white": {"kd": 0.5}},
    "objects": [{"sphere": {"center": [0, 0, 4], "radius": 2, "material": "white"}}]
  })",
                                "scene.json");

  EXPECT_EQ(scene.source, "scene.json");
  EXPECT_EQ(scene.image.width, 320);
  EXPECT_EQ(scene.image.height, 200);
  EXPECT_EQ(scene.camera.fovDegrees, 40.0f);
  ASSERT_EQ(scene.lights.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].kd, 0.5f);
  ASSERT_EQ(scene.shapes.size(), 1u);
  EXPECT_TRUE(
      hitsAt(intersect(*scene.shapes[0], kAlongZ), 2.0f, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}));
}

TEST(SceneFile, LeftOutValuesTakeTheirDefaults) {
  const Scene scene = loadScene(R"(
camera: {position: [0, 0, -5], look_at: [0, 0, 0]}
lights:
  - point: {position: [0, 5, 0]}
materials:
  plain: {}
objects:
  - sphere: {center: [0, 0, 0], radius: 1, material: plain}
)",
                                "defaults.yaml");

  const ImageSpec image;
  EXPECT_EQ(scene.image.width, image.width);
  EXPECT_EQ(scene.image.height, image.height);
  EXPECT_EQ(scene.image.background, Color(0.0f));
  EXPECT_EQ(scene.ambient, Color(0.0f));
  EXPECT_EQ(scene.camera.up, Vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(scene.camera.fovDegrees, 50.0f);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0]->color(), Color(1.0f));

  const Material defaults;
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& plain = scene.materials[0];
  EXPECT_EQ(plain.name, "plain");
  EXPECT_EQ(plain.color, defaults.color);
  EXPECT_EQ(plain.ka, defaults.ka);
  EXPECT_EQ(plain.kd, defaults.kd);
  EXPECT_EQ(plain.ks, defaults.ks);
  EXPECT_EQ(plain.n, defaults.n);
  EXPECT_EQ(plain.reflection, defaults.reflection);
  EXPECT_EQ(plain.transmission, defaults.transmission);
  EXPECT_EQ(plain.ior, defaults.ior);
}

TEST(SceneFile, AllowsASceneWithoutLightsOrObjects) {
  const Scene scene =
      loadScene("camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nobjects: []", "<stdin>");
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.materials.empty());
  EXPECT_TRUE(scene.shapes.empty());
}

TEST(SceneFile, IgnoresAnEmptyDocumentAfterTheScene) {
  const Scene scene = loadScene(
      "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nobjects: []\n---\n", "<stdin>");
  EXPECT_TRUE(scene.shapes.empty());
}

constexpr std::string_view kCameraAndMaterial = R"(
camera: {position: [0, 0, -5], look_at: [0, 0, 0]}
materials: {red: {}}
)";

Scene sceneWithObject(std::string_view object) {
  return loadScene(std::string(kCameraAndMaterial) + "objects:\n  - " + std::string(object),
                   "object.yaml");
}

TEST(SceneFile, TransformsTheVerticesOfATriangle) {
  // Scaled by 2, the triangle's corners are (-2, -2), (2, -2) and (0, 2);
  // turned half round y its normal faces -z; moved 5 along z.
  const Scene scene = sceneWithObject(
      "triangle: {vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], material: red,"
      " transform: {scale: 2, rotate: [0, 180, 0], translate: [0, 0, 5]}}");
  const Shape& triangle = *scene.shapes.at(0);
  EXPECT_TRUE(hitsAt(intersect(triangle, kAlongZ), 5.0f, {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}));
  EXPECT_TRUE(hitsAt(intersect(triangle, alongZFrom(1.5f, -1.5f)), 5.0f, {1.5f, -1.5f, 5.0f},
                     {0.0f, 0.0f, -1.0f}));
  EXPECT_TRUE(misses(intersect(triangle, alongZFrom(0.0f, 2.5f))));
}

TEST(SceneFile, FanTriangulatesAndTransformsMeshFaces) {
  // One square face: each of its two fan triangles covers one of the points tried.
  const Scene scene = sceneWithObject(
      "mesh: {vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], faces: [[0, 1, 2, 3]],"
      " material: red, transform: {translate: [0, 0, 3]}}");
  const Shape& mesh = *scene.shapes.at(0);
  EXPECT_TRUE(hitsAt(intersect(mesh, alongZFrom(0.5f, -0.5f)), 3.0f, {0.5f, -0.5f, 3.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(hitsAt(intersect(mesh, alongZFrom(-0.5f, 0.5f)), 3.0f, {-0.5f, 0.5f, 3.0f},
                     {0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(misses(intersect(mesh, alongZFrom(1.5f, 0.0f))));
}

TEST(SceneFile, TransformsSolidShapes) {
  // A unit sphere scaled to radius 2 around (0, 0, 10).
  const Scene scene = sceneWithObject(
      "sphere: {center: [0, 0, 0], radius: 1, material: red,"
      " transform: {scale: [2, 2, 2], translate: [0, 0, 10]}}");
  EXPECT_TRUE(hitsAt(intersect(*scene.shapes.at(0), kAlongZ), 8.0f, {0.0f, 0.0f, 8.0f},
                     {0.0f, 0.0f, -1.0f}));
}

TEST(SceneFile, ReportsWhereTheErrorIs) {
  try {
    loadScene("camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: -1}\nobjects: []",
              "<stdin>");
    FAIL() << "a negative field of view loaded";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), "<stdin>");
    EXPECT_EQ(error.line(), 1);
    EXPECT_EQ(error.column(), 57);
    EXPECT_EQ(error.message(), "'fov' in camera is -1; expected an angle in degrees > 0 and < 180");
    EXPECT_STREQ(error.what(),
                 "<stdin>:1:57: 'fov' in camera is -1; expected an angle in degrees > 0 and < 180");
  }
}

TEST(SceneFile, ReportsAMissingFile) {
  const std::filesystem::path path = kBadScenes / "does_not_exist.yaml";
  try {
    loadSceneFile(path);
    FAIL() << "a missing file loaded";
  } catch (const SceneError& error) {
    EXPECT_STREQ(
        error.what(),
        (path.string() + ": cannot open the scene file (No such file or directory)").c_str());
    EXPECT_EQ(error.line(), 0);
  }
}

TEST(SceneFile, SuggestsTheClosestSpellingOfAKey) {
  EXPECT_EQ(errorLoading("camera: {position: [0, 0, -5], lookAt: [0, 0, 0]}\nobjects: []"),
            "test.yaml:1:32: unknown key 'lookAt' in camera; did you mean 'look_at'?");
  EXPECT_EQ(errorLoading("camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nobjetcs: []"),
            "test.yaml:2:1: unknown key 'objetcs' in the scene; did you mean 'objects'?");
  EXPECT_EQ(errorLoading(std::string(kCameraAndMaterial) +
                         "objects: [sphere: {center: [0, 0, 0], radius: 1, material: red,"
                         " transform: {rotation: [0, 90, 0]}}]"),
            "test.yaml:4:77: unknown key 'rotation' in the transform of sphere; did you mean "
            "'rotate'?");
}

struct BadScene {
  std::string file;
  std::string message;  // the full message, after the directory of the bad scenes
};

void PrintTo(const BadScene& scene, std::ostream* out) { *out << scene.file; }

class BadSceneFile : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, IsRejectedWithItsMessage) {
  const std::filesystem::path path = kBadScenes / GetParam().file;
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  try {
    loadSceneFile(path);
    FAIL() << path << " loaded";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.what(), (kBadScenes / GetParam().message).string());
  }
}

INSTANTIATE_TEST_SUITE_P(
    SceneFile, BadSceneFile,
    ::testing::Values(
        BadScene{"typo_key.yaml",
                 "typo_key.yaml:8:7: unknown key 'radus' in sphere; did you mean 'radius'?"},
        BadScene{"unknown_key_far.yaml",
                 "unknown_key_far.yaml:4:33: unknown key 'shininess' in material 'red'; expected "
                 "one of: color, texture, bump, normal_map, ka, kd, ks, ks_texture, n, "
                 "reflection, transmission, ior, roughness, emission"},
        BadScene{"duplicate_key.yaml",
                 "duplicate_key.yaml:2:52: duplicate key 'position' in camera; a key may appear "
                 "only once"},
        BadScene{"wrong_type.yaml",
                 "wrong_type.yaml:6:22: 'center' in sphere is 5; expected a list of 3 numbers "
                 "[x, y, z]"},
        BadScene{"missing_key.yaml", "missing_key.yaml:6:13: sphere is missing 'radius'"},
        BadScene{"missing_camera.yaml", "missing_camera.yaml:2:1: the scene is missing 'camera'"},
        BadScene{"unknown_material.yaml",
                 "unknown_material.yaml:7:54: undefined material 'rde' in sphere; did you mean "
                 "'red'?"},
        BadScene{"no_materials.yaml",
                 "no_materials.yaml:4:54: undefined material 'red' in sphere; the scene defines "
                 "no materials"},
        BadScene{"nan_value.yaml",
                 "nan_value.yaml:6:26: a coordinate of 'center' in sphere is .nan; expected a "
                 "finite number"},
        BadScene{"infinite_value.yaml",
                 "infinite_value.yaml:4:37: 'ks' in material 'red' is .inf; expected a finite "
                 "number >= 0"},
        BadScene{"negative_radius.yaml",
                 "negative_radius.yaml:6:58: 'radius' in cylinder is -0.5; expected a number > 0"},
        BadScene{"negative_color.yaml",
                 "negative_color.yaml:3:16: a component of 'ambient' in the scene is -0.1; "
                 "expected a number >= 0"},
        BadScene{"zero_normal.yaml",
                 "zero_normal.yaml:6:39: 'normal' in plane is [0, 0, 0]; expected a direction, "
                 "not the zero vector"},
        BadScene{"zero_scale.yaml",
                 "zero_scale.yaml:10:26: 'scale' in the transform of sphere is [1, 0, 1]; "
                 "expected a scale that is not 0 on any axis"},
        BadScene{"up_parallel.yaml",
                 "up_parallel.yaml:3:3: camera looks straight along the default 'up' [0, 1, 0]; "
                 "expected an 'up' across the view from 'position' to 'look_at'"},
        BadScene{"look_at_position.yaml",
                 "look_at_position.yaml:4:12: 'look_at' in camera is the same point as "
                 "'position'; expected a point for the camera to look towards"},
        BadScene{"far_camera.yaml",
                 "far_camera.yaml:2:44: 'look_at' in camera is 1e30 units from 'position'; "
                 "expected a camera at most 1e15 units from the point it looks at"},
        BadScene{"absurd_ior.yaml",
                 "absurd_ior.yaml:4:77: 'ior' in material 'glass' is 1e30; expected a number "
                 "from 0.1 to 10"},
        BadScene{"fov_out_of_range.yaml",
                 "fov_out_of_range.yaml:2:57: 'fov' in camera is 180; expected an angle in "
                 "degrees > 0 and < 180"},
        BadScene{"fractional_width.yaml",
                 "fractional_width.yaml:2:16: 'width' in image is 640.5; expected a whole number "
                 "> 0"},
        BadScene{"string_number.yaml",
                 "string_number.yaml:2:57: 'fov' in camera is the string \"60\"; expected a "
                 "number"},
        BadScene{"word_for_number.yaml",
                 "word_for_number.yaml:2:29: 'height' in image is 'tall'; expected a whole "
                 "number > 0"},
        BadScene{"face_out_of_range.yaml",
                 "face_out_of_range.yaml:8:33: a vertex index of mesh is 3; expected an index "
                 "from 0 to 2, as 'vertices' has 3 points"},
        BadScene{"short_face.yaml",
                 "short_face.yaml:6:65: a face of mesh is [0, 1]; expected a list of 3 or more "
                 "vertex indices"},
        BadScene{"nonconvex_polygon.yaml",
                 "nonconvex_polygon.yaml:7:17: 'vertices' in polygon are not the corners of a "
                 "flat convex polygon; expected points in one plane, in order around a convex "
                 "outline"},
        BadScene{"nonplanar_polygon.yaml",
                 "nonplanar_polygon.yaml:6:25: 'vertices' in polygon are not the corners of a "
                 "flat convex polygon; expected points in one plane, in order around a convex "
                 "outline"},
        BadScene{"collinear_triangle.yaml",
                 "collinear_triangle.yaml:6:26: 'vertices' in triangle lie on one line; expected "
                 "the corners of a triangle"},
        BadScene{"inverted_box.yaml",
                 "inverted_box.yaml:6:32: 'max' in box is [1, 0, 1]; expected a corner greater "
                 "than 'min' [0, 1, 0] in x, y and z"},
        BadScene{"unknown_shape.yaml",
                 "unknown_shape.yaml:6:5: unknown shape 'sphre'; did you mean 'sphere'?"},
        BadScene{"unknown_light.yaml",
                 "unknown_light.yaml:4:5: unknown light type 'spot'; expected one of: point, "
                 "directional, rect, disk, sphere"},
        BadScene{"misindented_object.yaml",
                 "misindented_object.yaml:6:5: an item of 'objects' is a map with the keys "
                 "sphere, center, radius, material; expected a map with one key naming the "
                 "shape (plane, sphere, box, cylinder, cone, triangle, polygon, mesh) and its "
                 "properties indented under it"},
        BadScene{"unclosed_bracket.yaml",
                 "unclosed_bracket.yaml:4:8: invalid YAML: a list opened with '[' is not closed "
                 "with ']'"},
        BadScene{"mismatched_bracket.yaml",
                 "mismatched_bracket.yaml:4:30: invalid YAML: unexpected '}'; check that the "
                 "brackets before it are closed in order"},
        BadScene{"tab_indentation.yaml",
                 "tab_indentation.yaml:3:17: invalid YAML: unexpected ':' (wrong indentation, a "
                 "tab, or a value with ': ' that needs quotes?)"},
        BadScene{"leading_comma.yaml",
                 "leading_comma.yaml:2:1: invalid YAML: unexpected ','; expected a value (quote "
                 "text that starts with it)"},
        BadScene{"deep_nesting.yaml",
                 "deep_nesting.yaml:3:73: lists and maps nested more than 64 deep; a scene needs "
                 "only a few levels"},
        BadScene{"not_a_map.yaml",
                 "not_a_map.yaml:2:1: the scene is a list of 2 items; expected a map with the "
                 "keys image, camera, ambient, lights, materials, objects, animation"},
        BadScene{"two_documents.yaml",
                 "two_documents.yaml:5:1: a second YAML document (after '---'); expected the "
                 "scene file to hold one scene"},
        BadScene{"empty.yaml",
                 "empty.yaml: the scene file is empty; expected at least 'camera' and "
                 "'objects'"}),
    [](const ::testing::TestParamInfo<BadScene>& info) {
      return std::filesystem::path(info.param.file).stem().string();
    });

}  // namespace
}  // namespace rise
