// The scene loader: mesh files found from the scene file's folder, their
// errors reported at the 'file' value, keyframes checked against the model.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/scene_file.hpp"
#include "scene/shapes/keyframed_mesh.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/mesh_file_testing.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

using namespace mesh_file_testing;
using shape_testing::intersect;
using shape_testing::nearlyEqual;

class MeshScenes : public MeshFiles {
 protected:
  // A scene with one object, written beside the models, and loaded.
  Scene loadWith(const std::string& object) const {
    return loadSceneFile(write("scene.yaml", scene(object)));
  }

  // The message loading it fails with, after the scene file's path.
  std::string errorWith(const std::string& object) const {
    try {
      loadWith(object);
    } catch (const SceneError& error) {
      const std::string prefix = (directory_ / "scene.yaml").string();
      const std::string message = error.what();
      return message.starts_with(prefix) ? message.substr(prefix.size()) : message;
    }
    return "";
  }

  static std::string scene(const std::string& object) {
    return "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
           "materials: {m: {}}\n"
           "objects:\n"
           "  - mesh: " +
           object + "\n";
  }

  void copyModel(const fs::path& model, const std::string& name) const {
    fs::create_directories((directory_ / name).parent_path());
    fs::copy_file(model, directory_ / name);
  }
};

TEST_F(MeshScenes, FindsTheFileFromTheScenesFolderAndTransformsIt) {
  fs::create_directories(directory_ / "models");
  write("models/cube.off", kCubeOff);
  const Scene scene =
      loadWith("{file: models/cube.off, material: m, transform: {scale: 2, translate: [0, 0, 3]}}");
  ASSERT_EQ(scene.shapes.size(), 1u);
  ASSERT_NE(dynamic_cast<const TriangleMesh*>(scene.shapes[0].get()), nullptr);
  // The cube now spans z from 3 to 5; its near face looks at -z.
  const auto result = intersect(*scene.shapes[0], Ray{{1.0f, 1.0f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  EXPECT_TRUE(shape_testing::hitsAt(result, 8.0f, {1.0f, 1.0f, 3.0f}, {0.0f, 0.0f, -1.0f}));
  EXPECT_TRUE(nearlyEqual(result.surface.shadingNormal, {0.0f, 0.0f, -1.0f}));
}

TEST_F(MeshScenes, ShadesASphereModelWithInterpolatedNormals) {
  write("sphere.obj", sphereObj());
  const Scene scene = loadWith("{file: sphere.obj, material: m, transform: {scale: [1, 2, 1]}}");
  // Off-centre, the flat facet's normal and the smooth one part: the smooth
  // one is nearly the ellipsoid's, the gradient of x^2 + y^2 / 4 + z^2.
  const auto result = intersect(*scene.shapes.at(0), Ray{{0.3f, 0.5f, -5.0f}, {0.0f, 0.0f, 1.0f}});
  ASSERT_TRUE(result.found);
  const Vec3 p = result.surface.position;
  const Vec3 ellipsoidNormal = glm::normalize(Vec3(p.x, p.y / 4.0f, p.z));
  EXPECT_GT(glm::dot(result.surface.shadingNormal, ellipsoidNormal), std::cos(radians(1.5f)));
  EXPECT_NEAR(glm::length(result.surface.shadingNormal), 1.0f, 1e-5f);
  EXPECT_NE(result.surface.shadingNormal, result.surface.normal);
}

TEST_F(MeshScenes, AFrameGivesAStillMeshAndFramesAMovingOne) {
  copyModel(kSydney, "sydney.md2");
  const Scene still = loadWith("{file: sydney.md2, frame: 40, material: m}");
  ASSERT_NE(dynamic_cast<const TriangleMesh*>(still.shapes.at(0).get()), nullptr);
  EXPECT_EQ(still.shapes[0]->primitiveCount(), 679);
  const Scene moving = loadWith("{file: sydney.md2, frames: [40, 41], material: m}");
  ASSERT_NE(dynamic_cast<const KeyframedMesh*>(moving.shapes.at(0).get()), nullptr);
  EXPECT_EQ(moving.shapes[0]->primitiveCount(), 679);
}

TEST_F(MeshScenes, ReportsAFileThatCannotBeLoadedAtItsName) {
  EXPECT_EQ(errorWith("{file: models/absent.obj, material: m}"),
            ":4:18: cannot load mesh 'models/absent.obj': cannot open the file (No such file or "
            "directory)");
  truncatedCopy(kSydney, 5000);
  EXPECT_EQ(errorWith("{material: m, file: cut-5000.md2}"),
            ":4:31: cannot load mesh 'cut-5000.md2': the file is cut short: its 198 keyframes "
            "should end at byte 288824, but it has 5000 bytes");
  truncatedCopy(kSydney, 5000);
  EXPECT_EQ(errorWith("{material: m, file: cut-5000.md2, frame: 3}"),
            ":4:31: cannot load mesh 'cut-5000.md2': the file is cut short: its 198 keyframes "
            "should end at byte 288824, but it has 5000 bytes");
}

TEST_F(MeshScenes, ChecksTheKeyframes) {
  copyModel(kSydney, "sydney.md2");
  copyModel(kSpot, "spot.obj");
  EXPECT_EQ(errorWith("{file: sydney.md2, frame: 250, material: m}"),
            ":4:37: 'frame' in mesh is 250; expected a keyframe from 0 to 197, as 'sydney.md2' "
            "has 198");
  EXPECT_EQ(errorWith("{file: sydney.md2, frames: [0, 198], material: m}"),
            ":4:42: a keyframe of 'frames' in mesh is 198; expected a keyframe from 0 to 197, as "
            "'sydney.md2' has 198");
  EXPECT_EQ(errorWith("{file: sydney.md2, frame: -1, material: m}"),
            ":4:37: 'frame' in mesh is -1; expected a whole number >= 0");
  EXPECT_EQ(errorWith("{file: sydney.md2, frames: [1], material: m}"),
            ":4:38: 'frames' in mesh is [1]; expected a list of 2 keyframes [first, "
            "second]");
  EXPECT_EQ(errorWith("{file: sydney.md2, frame: 1, frames: [1, 2], material: m}"),
            ":4:48: mesh has both 'frame' and 'frames'; expected one of them");
  EXPECT_EQ(errorWith("{file: spot.obj, frame: 1, material: m}"),
            ":4:35: 'frame' in mesh picks keyframes of an MD2 model; 'spot.obj' is not an MD2 "
            "file");
}

TEST_F(MeshScenes, TakesEitherAFileOrVerticesAndFaces) {
  EXPECT_EQ(errorWith("{material: m}"),
            ":4:11: mesh needs either 'file' or 'vertices' and 'faces'");
  EXPECT_EQ(errorWith("{file: a.obj, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], material: m}"),
            ":4:18: mesh has both 'file' and 'vertices'; expected either a model 'file' or "
            "'vertices' and 'faces'");
  EXPECT_EQ(errorWith("{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], material: m}"),
            ":4:11: mesh is missing 'faces'");
  EXPECT_EQ(errorWith("{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]],"
                      " frame: 2, material: m}"),
            ":4:84: 'frame' in mesh picks keyframes of an MD2 model; expected it with a 'file', "
            "not with 'vertices' and 'faces'");
}

}  // namespace
}  // namespace rise
