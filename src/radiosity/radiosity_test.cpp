// Radiosity held to answers known without it: form factors in closed form,
// the furnace's geometric series, the light straight from a panel, and the
// two solvers' one solution.
#include "radiosity/radiosity.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"
#include "radiosity/form_factors.hpp"

namespace rise {
namespace {

// The settings a front end makes for the scene, on two threads, of patches
// of `patchSize` (0: chosen).
RenderSettings radiositySettings(const Scene& scene, float patchSize) {
  RenderRequest request;
  request.settings.threads = 2;
  request.settings.radiosity.patchSize = patchSize;
  return settingsFor(scene, request);
}

// The element nearest a point, on the side facing `towards`.
Color lightNear(const SolvedScene& solved, const Vec3& point, const Vec3& towards) {
  std::size_t nearest = 0;
  float best = kInfinity;
  for (std::size_t i = 0; i < solved.mesh.elementMesh.elements.size(); ++i) {
    const float d = glm::length(solved.mesh.elementMesh.elements[i].centre - point);
    if (d < best) best = d, nearest = i;
  }
  const Element& element = solved.mesh.elementMesh.elements[nearest];
  const int side = glm::dot(element.normal, towards - element.centre) >= 0.0f ? 0 : 1;
  return solved.solution.radiance[nearest][side];
}

// The form factor from the unit square at z = 0 (its normal +z) to a
// square `source` given as two triangles, averaged over m x m points of the
// first.
double squareToSquare(const std::array<Vec3, 4>& source, const Vec3& sourceNormal, int m) {
  double sum = 0.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const Vec3 point((i + 0.5f) / m, (j + 0.5f) / m, 0.0f);
      for (const std::array<Vec3, 3>& half : {std::array<Vec3, 3>{source[0], source[1], source[2]},
                                              std::array<Vec3, 3>{source[0], source[2], source[3]}})
        sum += formFactorToTriangle(point, {0.0f, 0.0f, 1.0f}, half, sourceNormal);
    }
  return sum / (m * m);
}

TEST(FormFactors, MatchTheClosedFormsOfTwoSquares) {
  // Facing each other one unit apart: 0.1998; meeting along an edge at a
  // right angle: 0.2000 (Cohen and Wallace 1993, chapter 4).
  const std::array<Vec3, 4> facing = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  const std::array<Vec3, 4> upright = {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1), Vec3(0, 0, 1)};
  std::array<double, 3> facingError{}, uprightError{};
  for (int step = 0; step < 3; ++step) {
    const int m = 4 << (2 * step);  // 4, 16, 64 points a side
    facingError[step] = std::abs(squareToSquare(facing, {0, 0, -1}, m) - 0.1998) / 0.1998;
    uprightError[step] = std::abs(squareToSquare(upright, {1, 0, 0}, m) - 0.2000) / 0.2000;
  }
  EXPECT_LT(facingError[2], 0.01);
  EXPECT_LT(uprightError[2], 0.01);
  // Closer as the points grow finer.
  EXPECT_LE(facingError[2], facingError[0]);
  EXPECT_LE(uprightError[2], uprightError[0]);
}

// Inside a closed box whose walls of reflectance rho emit Le everywhere, the
// light bounces for ever: Le (1 + rho + rho^2 + ...) = Le / (1 - rho).
TEST(Radiosity, TheFurnaceGlowsAsTheSeriesOfItsBouncesSums) {
  for (const RadiositySolver solver : kAllRadiositySolvers) {
    const Scene scene = loadScene(
        "camera: {position: [0, 0, 0], look_at: [0, 0, 1]}\n"
        "materials: {wall: {color: [1, 1, 1], kd: 0.6, emission: [0.2, 0.2, 0.2]}}\n"
        "objects: [{box: {min: [-1, -1, -1], max: [1, 2, 1], material: wall}}]\n",
        "furnace.yaml");
    RenderSettings settings = radiositySettings(scene, 0.25f);
    settings.radiosity.solver = solver;
    settings.radiosity.residual = 1e-4;
    const SolvedScene solved = solveRadiosity(scene, settings);
    double sum = 0.0, area = 0.0;
    for (std::size_t i = 0; i < solved.mesh.elementMesh.elements.size(); ++i) {
      // The inside of the box faces the eye: the back of its faces, whose
      // normals point out.
      sum += solved.solution.radiance[i][kBackSide].r * solved.mesh.elementMesh.elements[i].area;
      area += solved.mesh.elementMesh.elements[i].area;
    }
    EXPECT_NEAR(sum / area, 0.2 / (1.0 - 0.6), 0.015 * 0.5) << radiositySolverName(solver);
    EXPECT_LE(solved.solution.residual, 1e-4);
  }
}

TEST(Radiosity, TheFloorUnderAPanelTakesItsLightAsTheFormFactorSays) {
  const Scene scene = loadScene(
      "camera: {position: [278, 273, -800], look_at: [278, 273, 0], fov: 39.3}\n"
      "materials:\n"
      "  white: {color: [0.886, 0.699, 0.666], kd: 1}\n"
      "  light: {color: [0.78, 0.78, 0.78], kd: 1, emission: [18.387, 13.987, 6.754]}\n"
      "objects:\n"
      "  - polygon: {vertices: [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]], "
      "material: white}\n"
      "  - polygon: {vertices: [[343, 548.7, 227], [343, 548.7, 332], [213, 548.7, 332], [213, "
      "548.7, 227]], material: light}\n",
      "panel.yaml");
  const SolvedScene solved = solveRadiosity(scene, radiositySettings(scene, 20.0f));
  // The form factor from the floor's point under the panel's centre to the
  // panel, 0.014212 (integrated apart), times its emission and the floor's
  // reflectance.
  const Color floor = lightNear(solved, {278.0f, 0.0f, 279.5f}, {278.0f, 100.0f, 279.5f});
  EXPECT_NEAR(floor.r, 0.886f * 18.387f * 0.014212f, 0.01f * 0.2315f);
}

// The light of the room's walls away from the panel, where every pixel
// shows less than 1: its mean by channel.
Color meanOfTheRoom(const Image& image) {
  Color sum(0.0f);
  int count = 0;
  for (const Color& pixel : image.pixels())
    if (maxComponent(pixel) < 1.0f) sum += pixel, ++count;
  return sum / static_cast<float>(count);
}

// Two ways to one equation: the radiosity of the measured Cornell box and
// the path tracer's converged image agree, and so do radiosity's solvers.
TEST(Radiosity, DrawsTheCornellBoxAsThePathTracerDoes) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box-measured.yaml");
  RenderSettings settings = radiositySettings(scene, 0.0f);
  settings.width = settings.height = 48;
  settings.radiosity.residual = 1e-3;
  RenderObserver observer;
  const RenderResult progressive = RadiosityRenderer().render(scene, settings, observer);
  settings.radiosity.solver = RadiositySolver::GaussSeidel;
  const RenderResult swept = RadiosityRenderer().render(scene, settings, observer);
  settings.maxDepth = 64;
  settings.progression.samples = 256;
  const RenderResult traced = findRenderer("path-tracing")->render(scene, settings, observer);

  const Color byRadiosity = meanOfTheRoom(progressive.image);
  const Color bySweeps = meanOfTheRoom(swept.image);
  const Color byPaths = meanOfTheRoom(traced.image);
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(byRadiosity[channel], byPaths[channel], 0.04f * byPaths[channel]) << channel;
    EXPECT_NEAR(bySweeps[channel], byRadiosity[channel], 0.01f * byRadiosity[channel]) << channel;
  }
  EXPECT_GT(progressive.stats.value("shots"), 0.0);
  EXPECT_GT(swept.stats.value("sweeps"), 0.0);
  EXPECT_LE(progressive.stats.value("residual"), 1e-3);
}

}  // namespace
}  // namespace rise
