// Meshes read from model files: the real models in examples/models load with
// the triangle counts their authors give, smooth unit normals and texture
// coordinates; MD2 keyframes pose and animate the model; and every broken
// file (missing, unsupported, cut short, random bytes, empty) is refused with
// one message, never a crash. The messages are what users read, so the
// expected strings below are their specification.
#include "io/mesh_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io/scene_file.hpp"
#include "scene/shapes/keyframed_mesh.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/shapes/triangle_mesh.hpp"
#include "support/shape_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;
using shape_testing::intersect;
using shape_testing::nearlyEqual;

const fs::path kModels = fs::path(RISE_SOURCE_DIR) / "examples/models";
const fs::path kSydney = kModels / "sydney/sydney.md2";
const fs::path kRatamahatta = kModels / "ratamahatta/tris.md2";
const fs::path kSpot = kModels / "spot/spot_triangulated.obj";
const fs::path kTeapot = kModels / "utah-teapot/teapot-full_Mesh001.ply";
const fs::path kBunny = kModels / "stanford-bunny/stanford-bunny.obj";
const fs::path kCornellBox = kModels / "cornell-box/CornellBox-Original.obj";

// The reason loading `path` fails with, or "" when it loads.
std::string reasonLoading(const fs::path& path, int md2Keyframe = 0) {
  try {
    loadMeshFile(path, md2Keyframe);
  } catch (const MeshFileError& error) {
    return error.what();
  }
  return "";
}

Vec3 faceNormal(const MeshGeometry& mesh, const std::array<int, 3>& triangle) {
  return windingNormal(mesh.positions[triangle[0]], mesh.positions[triangle[1]],
                       mesh.positions[triangle[2]]);
}

class MeshFiles : public TemporaryFolderTest {
 protected:
  fs::path write(const std::string& name, const std::string& contents) const {
    std::ofstream(directory_ / name, std::ios::binary) << contents;
    return directory_ / name;
  }

  // The first `bytes` bytes of a real model, as a file of its own.
  fs::path truncatedCopy(const fs::path& model, std::size_t bytes) const {
    std::ifstream in(model, std::ios::binary);
    std::string start(bytes, '\0');
    in.read(start.data(), static_cast<std::streamsize>(bytes));
    return write("cut-" + std::to_string(bytes) + model.extension().string(), start);
  }

  fs::path randomBytes(const std::string& name, std::size_t bytes) const {
    std::mt19937 generator(7);
    std::string contents(bytes, '\0');
    for (char& c : contents) c = static_cast<char>(generator() & 0xff);
    return write(name, contents);
  }
};

struct ModelCount {
  fs::path file;
  std::size_t triangles;
  bool hasUvs;
};

void PrintTo(const ModelCount& model, std::ostream* out) { *out << model.file.filename(); }

class RealModel : public ::testing::TestWithParam<ModelCount> {};

TEST_P(RealModel, LoadsItsTrianglesWithUnitNormals) {
  const MeshGeometry mesh = loadMeshFile(GetParam().file);
  EXPECT_EQ(mesh.triangles.size(), GetParam().triangles);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const Vec3& normal : mesh.normals) ASSERT_NEAR(glm::length(normal), 1.0f, 1e-4f);
  EXPECT_EQ(mesh.uvs.size(), GetParam().hasUvs ? mesh.positions.size() : 0u);
}

// The counts are the authors': 679 and 666 triangles in the MD2 headers, the
// faces of the OBJ files with the Cornell box's 18 quads cut in two, the PLY
// header's 69310. The teapot's texture coordinates are all zero, which is
// none.
INSTANTIATE_TEST_SUITE_P(
    MeshFile, RealModel,
    ::testing::Values(ModelCount{kSydney, 679, true}, ModelCount{kRatamahatta, 666, true},
                      ModelCount{kSpot, 5856, true}, ModelCount{kCornellBox, 36, false},
                      ModelCount{kTeapot, 69310, false}, ModelCount{kBunny, 69451, false}),
    [](const ::testing::TestParamInfo<ModelCount>& info) {
      std::string name = info.param.file.stem().string();
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

TEST(MeshFile, ComputesSmoothNormalsForACurvedModelWithoutThem) {
  // Spot's OBJ has no normals: each vertex gets the average of the faces
  // around it, which differs from most of those faces' own normals but stays
  // on their side.
  const MeshGeometry spot = loadMeshFile(kSpot);
  int curvedCorners = 0;
  int corners = 0;
  for (const auto& triangle : spot.triangles) {
    const Vec3 face = faceNormal(spot, triangle);
    for (int vertex : triangle) {
      ++corners;
      EXPECT_GT(glm::dot(spot.normals[vertex], face), 0.0f);
      if (glm::dot(spot.normals[vertex], face) < std::cos(radians(1.0f))) ++curvedCorners;
    }
  }
  EXPECT_GT(curvedCorners, corners / 2);
}

TEST(MeshFile, KeepsTheNormalsOfAFileThatHasThem) {
  // The teapot's PLY gives a normal per vertex; they face the triangles' winding side.
  const MeshGeometry teapot = loadMeshFile(kTeapot);
  for (const auto& triangle : teapot.triangles)
    for (int vertex : triangle)
      ASSERT_GT(glm::dot(teapot.normals[vertex], faceNormal(teapot, triangle)), 0.0f);
}

TEST(MeshFile, TurnsMd2ModelsYUp) {
  // Sydney's first keyframe spans z from -24.01 to 30.94 Quake units in the
  // file, which has z up; Assimp's root node turns that into y.
  const MeshGeometry sydney = loadMeshFile(kSydney);
  float lowest = kInfinity;
  float highest = -kInfinity;
  for (const Vec3& position : sydney.positions) {
    lowest = std::min(lowest, position.y);
    highest = std::max(highest, position.y);
  }
  EXPECT_NEAR(lowest, -24.014f, 0.01f);
  EXPECT_NEAR(highest, 30.943f, 0.01f);
}

TEST(MeshFile, AKeyframePosesAnMd2Model) {
  const MeshGeometry standing = loadMeshFile(kSydney, 0);
  const MeshGeometry running = loadMeshFile(kSydney, 40);
  ASSERT_EQ(standing.triangles, running.triangles);
  ASSERT_EQ(standing.positions.size(), running.positions.size());
  float largestMove = 0.0f;
  for (std::size_t i = 0; i < standing.positions.size(); ++i)
    largestMove = std::max(largestMove, glm::length(running.positions[i] - standing.positions[i]));
  EXPECT_GT(largestMove, 5.0f);
  EXPECT_EQ(loadMeshFile(kSydney, 40).positions, running.positions);
}

TEST(MeshFile, CountsTheKeyframesOfAnMd2Model) {
  EXPECT_EQ(md2KeyframeCount(kSydney), 198);
  EXPECT_EQ(md2KeyframeCount(kRatamahatta), 198);
}

TEST(MeshFile, Md2KeyframesInterpolateFromTheFirstToTheSecond) {
  const std::vector<MeshGeometry> poses = loadMd2Keyframes(kSydney, 40, 41);
  ASSERT_EQ(poses.size(), 2u);
  const MeshGeometry& start = poses[0];
  const MeshGeometry& end = poses[1];
  const KeyframedMesh mesh(start, end, 0);
  // Triangle 100 alone, met along its normal from one unit away, at three
  // instants: its centre is where the keyframes put it, and halfway between.
  const auto centre = [](const MeshGeometry& pose) {
    const auto& [a, b, c] = pose.triangles[100];
    return (pose.positions[a] + pose.positions[b] + pose.positions[c]) / 3.0f;
  };
  for (const float time : {0.0f, 0.5f, 1.0f}) {
    const Vec3 expected = glm::mix(centre(start), centre(end), time);
    const auto& [a, b, c] = start.triangles[100];
    const Vec3 normal = windingNormal(glm::mix(start.positions[a], end.positions[a], time),
                                      glm::mix(start.positions[b], end.positions[b], time),
                                      glm::mix(start.positions[c], end.positions[c], time));
    const Ray ray{expected + normal, -normal, time};
    Hit hit;
    IntersectionCounters counters;
    ASSERT_TRUE(mesh.intersectPrimitive(100, ray, 0.0f, hit, counters)) << time;
    EXPECT_NEAR(hit.t, 1.0f, 1e-4f);
    EXPECT_TRUE(nearlyEqual(mesh.surfaceAt(ray, hit).position, expected, 1e-3f));
  }
}

TEST_F(MeshFiles, AppliesTheTransformsOfTheNodes) {
  // A glTF triangle in a node scaled by 2, under a node moved 5 along z.
  const fs::path file =
      write("triangle.gltf",
            R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
          "nodes": [{"children": [1], "translation": [0, 0, 5]}, {"mesh": 0, "scale": [2, 2, 2]}],
          "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
          "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)"
            R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
          "bufferViews": [{"buffer": 0, "byteLength": 36}],
          "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                         "min": [0, 0, 0], "max": [1, 1, 0]}]})");
  const MeshGeometry mesh = loadMeshFile(file);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  std::vector<Vec3> corners;
  for (int vertex : mesh.triangles[0]) corners.push_back(mesh.positions[vertex]);
  EXPECT_TRUE(nearlyEqual(corners[0], {0.0f, 0.0f, 5.0f}));
  EXPECT_TRUE(nearlyEqual(corners[1], {2.0f, 0.0f, 5.0f}));
  EXPECT_TRUE(nearlyEqual(corners[2], {0.0f, 2.0f, 5.0f}));
}

// An OFF unit cube: six quads, counter-clockwise seen from outside.
constexpr const char* kCubeOff = R"(OFF
8 6 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
)";

TEST_F(MeshFiles, KeepsTheEdgesOfABoxSharp) {
  // Faces meet at 90 degrees, more than the 80-degree crease angle: every
  // corner keeps its own face's normal, and the normals point outwards.
  const MeshGeometry cube = loadMeshFile(write("cube.off", kCubeOff));
  ASSERT_EQ(cube.triangles.size(), 12u);
  for (const auto& triangle : cube.triangles) {
    const Vec3 face = faceNormal(cube, triangle);
    const Vec3 centre =
        (cube.positions[triangle[0]] + cube.positions[triangle[1]] + cube.positions[triangle[2]]) /
        3.0f;
    EXPECT_GT(glm::dot(face, centre - Vec3(0.5f)), 0.0f);
    for (int vertex : triangle) EXPECT_TRUE(nearlyEqual(cube.normals[vertex], face));
  }
}

// A UV sphere of radius 1 as an OBJ without normals: 12 rings of 24 quads,
// with a vertex at each pole.
std::string sphereObj() {
  constexpr int kRings = 12;
  constexpr int kSegments = 24;
  std::string obj = "v 0 1 0\n";
  for (int ring = 1; ring < kRings; ++ring) {
    const float polar = kPi * static_cast<float>(ring) / kRings;
    for (int segment = 0; segment < kSegments; ++segment) {
      const float azimuth = 2.0f * kPi * static_cast<float>(segment) / kSegments;
      obj += "v " + std::to_string(std::sin(polar) * std::cos(azimuth)) + " " +
             std::to_string(std::cos(polar)) + " " +
             std::to_string(-std::sin(polar) * std::sin(azimuth)) + "\n";
    }
  }
  obj += "v 0 -1 0\n";
  const auto vertex = [](int ring, int segment) {  // OBJ indices start at 1
    return std::to_string(2 + (ring - 1) * kSegments + segment % kSegments);
  };
  const std::string south = std::to_string(2 + (kRings - 1) * kSegments);
  for (int segment = 0; segment < kSegments; ++segment) {
    obj += "f 1 " + vertex(1, segment) + " " + vertex(1, segment + 1) + "\n";
    for (int ring = 1; ring + 1 < kRings; ++ring)
      obj += "f " + vertex(ring, segment) + " " + vertex(ring + 1, segment) + " " +
             vertex(ring + 1, segment + 1) + " " + vertex(ring, segment + 1) + "\n";
    obj += "f " + vertex(kRings - 1, segment) + " " + south + " " +
           vertex(kRings - 1, segment + 1) + "\n";
  }
  return obj;
}

TEST_F(MeshFiles, ComputedNormalsOfASphereAreNearlyRadial) {
  // The facets are 15 degrees apart, so that a flat normal strays up to 7.5
  // degrees from the sphere's at a vertex; the smooth normals stay within 3.
  const MeshGeometry sphere = loadMeshFile(write("sphere.obj", sphereObj()));
  EXPECT_EQ(sphere.triangles.size(), 2u * 24u + 2u * 24u * 10u);
  EXPECT_EQ(sphere.positions.size(), 2u + 11u * 24u);
  for (std::size_t i = 0; i < sphere.positions.size(); ++i)
    EXPECT_GT(glm::dot(sphere.normals[i], glm::normalize(sphere.positions[i])),
              std::cos(radians(3.0f)))
        << "vertex " << i;
}

TEST_F(MeshFiles, AMissingFileOrAFolderIsRefused) {
  EXPECT_EQ(reasonLoading(directory_ / "absent.obj"),
            "cannot open the file (No such file or directory)");
  fs::create_directories(directory_ / "folder.obj");
  EXPECT_EQ(reasonLoading(directory_ / "folder.obj"), "cannot open the file (Is a directory)");
}

TEST_F(MeshFiles, AnUnsupportedFormatIsRefused) {
  EXPECT_EQ(reasonLoading(write("notes.txt", "not a model")),
            "'.txt' is not a model format that RISE reads; expected .obj, .ply, .md2, .gltf, "
            ".glb, .off or .3ds");
  EXPECT_EQ(reasonLoading(write("model", "v 0 0 0\n")),
            "the file name has no extension to tell its format; expected .obj, .ply, .md2, "
            ".gltf, .glb, .off or .3ds");
}

TEST_F(MeshFiles, AnEmptyFileIsRefused) {
  for (const std::string name : {"empty.obj", "empty.ply", "empty.md2"})
    EXPECT_EQ(reasonLoading(write(name, "")), "the file is empty") << name;
}

TEST_F(MeshFiles, RandomBytesAreRefused) {
  EXPECT_EQ(reasonLoading(randomBytes("noise.md2", 4000)),
            "not an MD2 model: it does not start with 'IDP2'");
  EXPECT_EQ(reasonLoading(randomBytes("noise.ply", 4000)),
            "not a PLY model: it does not start with 'ply'");
  EXPECT_NE(reasonLoading(randomBytes("noise.obj", 4000)), "");
}

TEST_F(MeshFiles, AFileWithoutTrianglesIsRefused) {
  EXPECT_EQ(reasonLoading(write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n")),
            "the file has no triangles");
  EXPECT_EQ(reasonLoading(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")),
            "the file has no faces (Assimp: Validation failed: Mesh contains no faces)");
}

TEST_F(MeshFiles, ATruncatedMd2ModelIsRefused) {
  EXPECT_EQ(reasonLoading(truncatedCopy(kSydney, 10)),
            "the file is too short for an MD2 header: 10 of 68 bytes");
  EXPECT_EQ(reasonLoading(truncatedCopy(kSydney, 5000)),
            "the file is cut short: its 198 keyframes should end at byte 288824, but it has 5000 "
            "bytes");
  // Past the keyframes, the OpenGL commands are missing.
  EXPECT_EQ(reasonLoading(truncatedCopy(kSydney, fs::file_size(kSydney) - 1)),
            "the file is cut short: its 3326 OpenGL commands should end at byte 302128, but it "
            "has 302127 bytes");
}

TEST_F(MeshFiles, ATruncatedObjModelIsRefused) {
  // Spot's first 2000 bytes hold vertices and no face.
  EXPECT_EQ(reasonLoading(truncatedCopy(kSpot, 2000)),
            "the file has no faces (Assimp: Validation failed: Mesh contains no faces)");
  EXPECT_EQ(reasonLoading(truncatedCopy(kCornellBox, 100)),
            "the file has no meshes (Assimp: Validation failed: aiScene::mNumMeshes is 0. At "
            "least one mesh must be there)");
}

TEST_F(MeshFiles, ATruncatedPlyModelIsRefused) {
  // The teapot's header ends at byte 265: Assimp would wait forever for its end.
  for (const std::size_t bytes : {3u, 20u, 100u, 264u})
    EXPECT_NE(reasonLoading(truncatedCopy(kTeapot, bytes)), "") << bytes;
  EXPECT_EQ(reasonLoading(truncatedCopy(kTeapot, 100)),
            "the PLY header is cut short: it has no 'end_header' line");
  EXPECT_EQ(reasonLoading(truncatedCopy(kTeapot, 50000)),
            "the file is cut short or corrupt: its PLY header promises 34768 'vertex' elements, "
            "of at least 1112576 bytes, but 49735 bytes follow the header");
  EXPECT_EQ(reasonLoading(truncatedCopy(kTeapot, fs::file_size(kTeapot) - 100)),
            "a face refers to a vertex that the file does not have (Assimp: Validation failed: "
            "aiMesh::mFaces[69302]::mIndices[0] is out of range)");
}

TEST_F(MeshFiles, TruncatedModelsAreRefusedAtEveryLength) {
  // Cuts spread over each file: each must fail with a reason or load, and
  // none may crash or hang.
  for (const fs::path& model : {kSydney, kSpot, kTeapot}) {
    const std::size_t size = fs::file_size(model);
    for (std::size_t bytes = 0; bytes < size; bytes += size / 23 + 1) {
      try {
        loadMeshFile(truncatedCopy(model, bytes));
      } catch (const MeshFileError& error) {
        EXPECT_NE(std::string(error.what()), "") << model << " cut at " << bytes;
      }
    }
  }
}

// The scene loader: mesh files found from the scene file's folder, their
// errors reported at the 'file' value, keyframes checked against the model.
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
