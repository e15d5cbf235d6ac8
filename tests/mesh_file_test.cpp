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
#include "support/mesh_file_testing.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;
using namespace mesh_file_testing;
using shape_testing::intersect;
using shape_testing::nearlyEqual;

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
            ".glb, .off, .3ds or .stl");
  EXPECT_EQ(reasonLoading(write("model", "v 0 0 0\n")),
            "the file name has no extension to tell its format; expected .obj, .ply, .md2, "
            ".gltf, .glb, .off, .3ds or .stl");
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

TEST_F(MeshFiles, APlyModelWithAFaceOfNoCornersIsRefused) {
  // Assimp's triangulation would stop the program on an assertion.
  EXPECT_EQ(reasonLoading(write("no-corners.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 2\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n0\n3 0 1 2\n")),
            "face 0 has no corners, as in a corrupt file");
}

TEST_F(MeshFiles, AModelWithNoPointsToDrawIsRefused) {
  // Assimp drops such a mesh, and with none left its C interface crashed.
  const std::string reason =
      "no mesh of the file has points to draw: in each, a coordinate is not a number, or every "
      "point that its faces use is the same";
  EXPECT_EQ(reasonLoading(write("one-point.off", "OFF\n3 1 0\n1 2 3\n1 2 3\n1 2 3\n3 0 1 2\n")),
            reason);
  EXPECT_EQ(reasonLoading(write("infinite.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e39 0\n3 0 1 2\n")),
            reason);
  // Points apart are drawn.
  EXPECT_EQ(reasonLoading(write("apart.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")), "");
}

TEST_F(MeshFiles, APlyHeaderWithWordsPlyDoesNotHaveIsRefused) {
  // As a fuzzer made it: Assimp stopped RISE on an assertion reading it.
  const std::string misspeltKeyword = R"(ply
format ascii 1.0
element vertex 4
property float x
prpoerty float y
property float z
element face 2
pr
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
en!_header
0 0 0
1 0 0
1 1operty list uchar int vertex_indices
end_header
0 0 0
1 0 0
1 1 0
0 1 0
3 0 1 2
3 0 2 3
)";
  EXPECT_EQ(reasonLoading(write("misspelt.ply", misspeltKeyword)),
            "the PLY header is corrupt: line 5: 'prpoerty' is not a PLY keyword (format, element, "
            "property, comment, end_header)");
  // An unknown type, and an end glued to what follows, made Assimp read for ever.
  const std::string start = "ply\nformat ascii 1.0\nelement vertex 1\n";
  EXPECT_EQ(reasonLoading(write("unknown-type.ply", start + "property flaot x\nend_header\n0\n")),
            "the PLY header is corrupt: line 4: 'flaot' is not a PLY type (char, uchar, short, "
            "ushort, int, uint, float, double)");
  EXPECT_EQ(reasonLoading(write("glued-end.ply", start + "property float x\nend_header3 0 1\n")),
            "the PLY header is corrupt: 'end_header' is not a line of its own");
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

}  // namespace
}  // namespace rise
