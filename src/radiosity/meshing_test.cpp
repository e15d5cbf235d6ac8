// Radiosity's mesh: form factors over a closed box's elements, patches that
// gather a model's small triangles, and the cuts of adaptive subdivision,
// drawn without T-vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"
#include "radiosity/form_factor_matrix.hpp"
#include "radiosity/radiosity.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace rise {
namespace {

// The settings a front end makes for the scene, on two threads, of patches
// of `patchSize`, the image `width` wide where given.
RenderSettings radiositySettings(const Scene& scene, float patchSize,
                                 std::optional<int> width = {}) {
  RenderRequest request;
  request.settings.threads = 2;
  request.settings.radiosity.patchSize = patchSize;
  request.image.width = width;
  return settingsFor(scene, request);
}

// Inside a closed box, all that leaves a wall reaches another wall: each
// row of form factors sums to 1; and A_i F_ij = A_j F_ji; by either method.
TEST(FormFactors, SumToOneInAClosedBoxAndAreReciprocal) {
  const Scene scene = loadScene(
      "camera: {position: [0, 0, 0], look_at: [0, 0, 1]}\n"
      "materials: {white: {color: [1, 1, 1]}}\n"
      "objects: [{box: {min: [-1, -1, -1], max: [1, 0.5, 1.5], material: white}}]\n",
      "box.yaml");
  for (const FormFactorMethod method : kAllFormFactorMethods) {
    RenderSettings settings = radiositySettings(scene, 0.5f);
    settings.radiosity.formFactors = method;
    const RadiosityMesh mesh = meshForRadiosity(scene, settings);
    const std::vector<Patch>& patches = mesh.patchMesh.patches;
    ASSERT_GT(patches.size(), 50u);
    const Scene elements = elementsAsScene(scene, mesh.elementMesh);
    const SceneIntersector blockers(elements, settings.accel, settings.threads);
    const Workers workers(settings.threads);
    const FormFactorMatrix formFactors(mesh, blockers, settings.radiosity, workers, 1e-4f);
    // By wall, each known by its normal: A_a F_ab = the sum over its
    // patches i of A_i F_i->b.
    const auto wallOf = [&](std::size_t i) { return facingOf(patches[i].normal); };
    std::array<std::array<double, 6>, 6> shared{};
    double worstSum = 0.0;
    for (std::size_t i = 0; i < patches.size(); ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < patches.size(); ++j) {
        sum += formFactors(i, j);
        shared[wallOf(i)][wallOf(j)] += patches[i].area * formFactors(i, j);
      }
      worstSum = std::max(worstSum, std::abs(sum - 1.0));
    }
    double worstReciprocity = 0.0;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (shared[a][b] > 0.0)
          worstReciprocity =
              std::max(worstReciprocity, std::abs(shared[a][b] - shared[b][a]) / shared[a][b]);
    EXPECT_LT(worstSum, 0.01) << formFactorMethodName(method);
    EXPECT_LT(worstReciprocity, 0.01) << formFactorMethodName(method);
  }
}

const char* const kModelScene =
    "camera: {position: [0, 1, -4], look_at: [0, 0, 0]}\n"
    "materials: {white: {color: [1, 1, 1]}}\n"
    "objects:\n"
    "  - {sphere: {center: [0, 0, 0], radius: 1, material: white}}\n"
    "  - {polygon: {vertices: [[-3, -1, -3], [-3, -1, 3], [3, -1, 3], [3, -1, -3]], "
    "material: white}}\n";

TEST(Patches, GatherSmallTrianglesIntoFewPatchesEachElementInOne) {
  const Scene scene = loadScene(kModelScene, "sphere.yaml");
  RenderSettings settings = radiositySettings(scene, 0.8f);
  settings.tessellation = 48;  // a sphere of many small triangles
  const TessellatedScene triangles = tessellateForRaster(scene, settings);
  const ElementMesh elements = meshElements(triangles, 0.8f);
  const PatchMesh patches = gatherPatches(elements, 0.8f);
  EXPECT_EQ(patches.patches.size(), patchCount(triangles, 0.8f));
  EXPECT_LT(patches.patches.size() * 10, elements.elements.size());
  std::vector<int> inPatches(elements.elements.size(), 0);
  for (std::size_t p = 0; p < patches.patches.size(); ++p) {
    const Patch& patch = patches.patches[p];
    float area = 0.0f;
    for (const int e : patch.elements) {
      ++inPatches[e];
      EXPECT_EQ(patches.patchOf[e], static_cast<int>(p));
      EXPECT_EQ(elements.elements[e].shape, elements.elements[patch.elements.front()].shape);
      EXPECT_GT(glm::dot(elements.elements[e].normal, patch.normal), 0.0f);
      area += elements.elements[e].area;
    }
    EXPECT_NEAR(patch.area, area, 1e-4f * area);
    EXPECT_LE(patch.facingArea, patch.area * 1.0001f);
  }
  for (const int count : inPatches) EXPECT_EQ(count, 1);
}

// A point light and a box over a floor: a sharp shadow, which adaptive
// subdivision follows.
const char* const kShadowScene =
    "camera: {position: [0, 6, -0.01], look_at: [0, 0, 0], fov: 50}\n"
    "image: {width: 96, height: 64, background: [0, 0, 0]}\n"
    "materials: {white: {color: [1, 1, 1], kd: 0.7}}\n"
    "lights: [{point: {position: [0.3, 4, 0.2], color: [1, 1, 1]}}]\n"
    "objects:\n"
    "  - {box: {min: [-0.5, 0.5, -0.5], max: [0.5, 1.0, 0.5], material: white}}\n"
    "  - {polygon: {vertices: [[-3, 0, -3], [-3, 0, 3], [3, 0, 3], [3, 0, -3]], "
    "material: white}}\n";

// Whether `point` lies on the segment from a to b, strictly between them.
bool strictlyWithin(const Vec3& point, const Vec3& a, const Vec3& b) {
  const Vec3 along = b - a;
  const float t = glm::dot(point - a, along) / glm::dot(along, along);
  if (!(t > 1e-4f && t < 1.0f - 1e-4f)) return false;
  return glm::length(a + t * along - point) < 1e-5f * glm::length(along);
}

TEST(AdaptiveSubdivision, CutsAtTheShadowsEdgeAndDrawsNoTVertex) {
  const Scene scene = loadScene(kShadowScene, "shadow.yaml");
  const SolvedScene solved = solveRadiosity(scene, radiositySettings(scene, 0.75f));
  EXPECT_GT(solved.solution.elementsCut, 20u);
  const TessellatedScene& drawn = solved.mesh.elementMesh.triangles;
  // No corner of a drawn face lies inside another's side.
  std::vector<Vec3> corners;
  for (const SceneFace& face : drawn.faces)
    for (const int v : face.vertices) corners.push_back(drawn.vertices[v].position);
  int tVertices = 0;
  for (const SceneFace& face : drawn.faces)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = drawn.vertices[face.vertices[k]].position,
                 b = drawn.vertices[face.vertices[(k + 1) % 3]].position;
      for (const Vec3& corner : corners) tVertices += strictlyWithin(corner, a, b) ? 1 : 0;
    }
  EXPECT_EQ(tVertices, 0);
}

TEST(AdaptiveSubdivision, LeavesNoCrackInTheLitFloor) {
  const Scene scene = loadScene(kShadowScene, "shadow.yaml");
  RenderObserver observer;
  const RenderResult result =
      RadiosityRenderer().render(scene, radiositySettings(scene, 0.75f, 192), observer);
  const Image& image = result.image;
  float brightest = 0.0f;
  for (const Color& pixel : image.pixels()) brightest = std::max(brightest, luminance(pixel));
  // A pixel darker by a tenth than both its neighbours in a row or a
  // column, where its four neighbours are lit (away from the shadow's
  // edge): the black background through a crack, or a seam.
  int cracks = 0;
  for (int y = 1; y + 1 < image.height(); ++y)
    for (int x = 1; x + 1 < image.width(); ++x) {
      const float at = luminance(image.at(x, y));
      const float left = luminance(image.at(x - 1, y)), right = luminance(image.at(x + 1, y)),
                  up = luminance(image.at(x, y - 1)), down = luminance(image.at(x, y + 1));
      if (std::min({left, right, up, down}) < 0.5f * brightest) continue;
      if (at < 0.9f * std::min(left, right) || at < 0.9f * std::min(up, down)) ++cracks;
    }
  EXPECT_EQ(cracks, 0);
}

}  // namespace
}  // namespace rise
