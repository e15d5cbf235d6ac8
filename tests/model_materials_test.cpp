// A model in its own materials: an OBJ file's MTL materials become the
// scene's (Kd, Ka, Ks, Ns, Ke, d, Ni and map_Kd), the model a mesh for each,
// a material in the scene still overriding them all; and the Cornell box's
// red and green walls and glowing panel as every algorithm draws them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "algorithms/registry.hpp"
#include "io/scene_file.hpp"
#include "support/mesh_file_testing.hpp"

namespace rise {
namespace {

using namespace mesh_file_testing;

// Two quads side by side in the z = 0 plane, the left one red and glowing,
// the right one grey glass with a texture.
constexpr const char* kTwoQuadsObj = R"(mtllib two.mtl
v -2 -1 0
v 0 -1 0
v 0 1 0
v -2 1 0
v 2 -1 0
v 2 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl red
f 1/1 2/2 3/3 4/4
usemtl glass
f 2/1 5/2 6/3 3/4
)";

constexpr const char* kTwoQuadsMtl = R"(newmtl red
Ka 0.4 0.05 0.05
Kd 0.8 0.1 0.1
Ks 0.5 0.25 0
Ns 40
Ke 2 1 0.5

newmtl glass
Kd 0.5 0.5 0.5
d 0.25
Ni 1.5
map_Kd textures\checker.ppm
)";

// A 2x2 checkerboard in the binary PPM format.
const std::string kCheckerPpm = std::string("P6\n2 2\n255\n") + std::string(3, '\xff') +
                                std::string(6, '\0') + std::string(3, '\xff');

class ModelMaterials : public MeshFiles {
 protected:
  void SetUp() override {
    MeshFiles::SetUp();
    write("two.obj", kTwoQuadsObj);
    write("two.mtl", kTwoQuadsMtl);
    std::filesystem::create_directories(directory_ / "textures");
    write("textures/checker.ppm", kCheckerPpm);
  }

  Scene loadWith(const std::string& objects) const {
    return loadSceneFile(write("scene.yaml",
                               "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
                               "materials: {m: {color: [0, 0, 1]}}\n"
                               "objects:\n" +
                                   objects));
  }

  std::string errorWith(const std::string& objects) const {
    try {
      loadWith(objects);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "";
  }
};

TEST_F(ModelMaterials, AModelWithoutAMaterialWearsItsFilesOwn) {
  const Scene scene = loadWith("  - mesh: {file: two.obj}\n");
  ASSERT_EQ(scene.shapes.size(), 2u);
  const Material& red = scene.materialOf(*scene.shapes[0]);
  EXPECT_EQ(red.name, "red of two.obj");
  EXPECT_EQ(red.color, Color(0.8f, 0.1f, 0.1f));
  EXPECT_FLOAT_EQ(red.kd, 1.0f);
  EXPECT_FLOAT_EQ(red.ka, 0.5f);  // Ka's largest channel over Kd's
  EXPECT_FLOAT_EQ(red.ks, 0.5f);
  EXPECT_FLOAT_EQ(red.n, 40.0f);
  EXPECT_EQ(red.emission, Color(2.0f, 1.0f, 0.5f));
  EXPECT_FALSE(red.isTransparent());
  EXPECT_EQ(red.texture, nullptr);

  const Material& glass = scene.materialOf(*scene.shapes[1]);
  EXPECT_EQ(glass.name, "glass of two.obj");
  EXPECT_FLOAT_EQ(glass.transmission, 0.75f);
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);
  EXPECT_FLOAT_EQ(glass.ka, 0.0f);  // a file without Ka reflects no ambient light
  ASSERT_NE(glass.texture, nullptr);         // found from the model's folder, past the backslash

  EXPECT_EQ(scene.shapeNames[0], "mesh at line 4 wearing red of two.obj");
  EXPECT_EQ(scene.shapeObjects, (std::vector<int>{0, 0}));
}

TEST_F(ModelMaterials, EachPartHoldsTheTrianglesOfItsMaterial) {
  const Scene scene = loadWith("  - mesh: {file: two.obj, transform: {translate: [0, 0, 1]}}\n");
  ASSERT_EQ(scene.shapes.size(), 2u);
  // The red quad is the left one, both moved to z = 1.
  EXPECT_LT(scene.shapes[0]->bounds().max.x, 0.001f);
  EXPECT_GT(scene.shapes[1]->bounds().min.x, -0.001f);
  EXPECT_FLOAT_EQ(scene.shapes[1]->bounds().min.z, 1.0f);
}

TEST_F(ModelMaterials, TheScenesMaterialOverridesTheFilesAndModelsShareThem) {
  const Scene overridden = loadWith("  - mesh: {file: two.obj, material: m}\n");
  ASSERT_EQ(overridden.shapes.size(), 1u);
  EXPECT_EQ(overridden.materialOf(*overridden.shapes[0]).name, "m");

  const Scene twice = loadWith(
      "  - mesh: {file: two.obj}\n"
      "  - mesh: {file: two.obj, transform: {translate: [0, 3, 0]}}\n");
  ASSERT_EQ(twice.shapes.size(), 4u);
  EXPECT_EQ(twice.materials.size(), 3u);  // m, and the file's two, once
  EXPECT_EQ(twice.shapes[0]->material(), twice.shapes[2]->material());
  EXPECT_EQ(twice.shapeObjects, (std::vector<int>{0, 0, 1, 1}));
}

TEST_F(ModelMaterials, AModelThatDescribesNoMaterialNeedsOne) {
  write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string message = errorWith("  - mesh: {file: plain.obj}\n");
  EXPECT_NE(message.find("scene.yaml:4:11: mesh 'plain.obj' needs a 'material': the file "
                         "describes none of its own"),
            std::string::npos)
      << message;
}

TEST_F(ModelMaterials, AnImpossibleValueOrAMissingTextureIsReportedWithItsMaterial) {
  write("two.mtl",
        std::string(kTwoQuadsMtl).replace(std::string(kTwoQuadsMtl).find("Kd 0.8"), 6, "Kd -0.8"));
  EXPECT_NE(errorWith("  - mesh: {file: two.obj}\n")
                .find("cannot load mesh 'two.obj': material 'red' has Kd -0.8; expected three "
                      "numbers >= 0"),
            std::string::npos)
      << errorWith("  - mesh: {file: two.obj}\n");

  write("two.mtl", kTwoQuadsMtl);
  std::filesystem::remove(directory_ / "textures/checker.ppm");
  const std::string message = errorWith("  - mesh: {file: two.obj}\n");
  EXPECT_NE(message.find("cannot load the texture 'textures/checker.ppm' of material 'glass' of "
                         "mesh 'two.obj'"),
            std::string::npos)
      << message;
}

TEST_F(ModelMaterials, KeyframesNeedTheObjectsMaterial) {
  const std::string message = errorWith("  - mesh: {file: two.obj, frame: 1}\n");
  EXPECT_NE(message.find("expected a 'material' beside it"), std::string::npos) << message;
}

// The Cornell box's model in its MTL file's materials, seen from its front.
Scene cornellBox(const std::string& lights) {
  return loadScene(
      "image: {width: 48, height: 48, background: [0, 0, 0]}\n"
      "camera: {position: [0, 1, 3.9], look_at: [0, 1, 0], fov: 39}\n"
      "ambient: [0.1, 0.1, 0.1]\n" +
          lights +
          "objects:\n"
          "  - mesh: {file: " +
          kCornellBox.string() + "}\n",
      "cornell.yaml");
}

RenderResult render(const Scene& scene, const std::string& algorithm, int samples = 1) {
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.threads = 2;
  settings.progression.samples = samples;
  RenderObserver observer;
  return findRenderer(algorithm)->render(scene, settings, observer);
}

TEST(CornellBoxModel, EveryAlgorithmDrawsItsRedAndGreenWalls) {
  const Scene scene = cornellBox("lights:\n  - point: {position: [0, 1.8, 0], color: [1, 1, 1]}\n");
  for (const char* algorithm :
       {"depth-sort", "area-subdivision", "z-buffer", "scanline", "ray-tracing",
        "distributed-ray-tracing", "hybrid", "path-tracing"}) {
    const Image& image = render(scene, algorithm, 4).image;
    // Halfway up, a few pixels in from each side: the left wall, the right wall.
    const Color left = image.at(3, 24);
    const Color right = image.at(44, 24);
    EXPECT_GT(left.r, 3.0f * left.g) << algorithm;
    EXPECT_GT(right.g, 2.0f * right.r) << algorithm;
  }
}

TEST(CornellBoxModel, ItsPanelLightsTheRoomForThePathTracer) {
  const Scene scene = cornellBox("");
  const Image& image = render(scene, "path-tracing", 16).image;
  // The floor between the tall block and the red wall, lit by the panel
  // alone: about Kd / pi times the panel's Ke (17, 12, 4), its area and the
  // cosines over the distance squared, (0.13, 0.09, 0.03) for its direct light.
  Color floor(0.0f);
  for (int y = 43; y <= 45; ++y)
    for (int x = 8; x <= 12; ++x) floor += image.at(x, y) / 15.0f;
  EXPECT_GT(floor.r, 0.1f);
  EXPECT_LT(floor.r, 0.3f);
  EXPECT_GT(floor.r, 2.0f * floor.b);
}

}  // namespace
}  // namespace rise
