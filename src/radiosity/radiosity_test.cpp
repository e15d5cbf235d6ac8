// Radiosity held to answers known without it: the furnace's geometric
// series, the light straight from a panel, the path tracer's image of the
// Cornell box, and its solvers' and form factors' one solution (the form
// factors alone: form_factors_test.cpp).
#include "radiosity/radiosity.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"

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
  settings.radiosity.formFactors = FormFactorMethod::Hemicube;
  const RenderResult byHemicubes = RadiosityRenderer().render(scene, settings, observer);
  settings.radiosity.formFactors = FormFactorMethod::Rays;
  settings.radiosity.solver = RadiositySolver::GaussSeidel;
  const RenderResult swept = RadiosityRenderer().render(scene, settings, observer);
  settings.maxDepth = 64;
  settings.progression.samples = 256;
  const RenderResult traced = findRenderer("path-tracing")->render(scene, settings, observer);

  const Color byRadiosity = meanOfTheRoom(progressive.image);
  const Color bySweeps = meanOfTheRoom(swept.image);
  const Color byHemicube = meanOfTheRoom(byHemicubes.image);
  const Color byPaths = meanOfTheRoom(traced.image);
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(byRadiosity[channel], byPaths[channel], 0.04f * byPaths[channel]) << channel;
    EXPECT_NEAR(bySweeps[channel], byRadiosity[channel], 0.01f * byRadiosity[channel]) << channel;
    // The hemicube's texels miss a little more of the small patches far off.
    EXPECT_NEAR(byHemicube[channel], byPaths[channel], 0.05f * byPaths[channel]) << channel;
  }
  EXPECT_GT(byHemicubes.stats.value("hemicube_texels"), 0.0);
  EXPECT_GT(progressive.stats.value("shots"), 0.0);
  EXPECT_GT(swept.stats.value("sweeps"), 0.0);
  EXPECT_LE(progressive.stats.value("residual"), 1e-3);
}

// The share of pixels whose colours differ by more than 2% of the brighter.
double shareDiffering(const Image& a, const Image& b) {
  int differing = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const float brighter = std::max(maxComponent(a.at(x, y)), maxComponent(b.at(x, y)));
      if (maxComponent(glm::abs(a.at(x, y) - b.at(x, y))) > 0.02f * brighter + 1e-4f) ++differing;
    }
  return static_cast<double>(differing) / (a.width() * a.height());
}

// Each visible-surface algorithm draws the solution as the z-buffer does,
// at another size and aspect than the examples'.
TEST(Radiosity, EveryVisibleSurfaceAlgorithmDrawsTheSolution) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box.yaml");
  RenderSettings settings = radiositySettings(scene, 0.0f);
  settings.width = 72;
  settings.height = 40;
  const RadiosityRenderer radiosity;
  RenderObserver observer;
  const RenderResult byZBuffer = radiosity.render(scene, settings, observer);
  for (const RadiosityDisplay display : kAllRadiosityDisplays) {
    settings.radiosity.display = display;
    const RenderResult drawn = radiosity.render(scene, settings, observer);
    EXPECT_LT(shareDiffering(drawn.image, byZBuffer.image), 0.01) << radiosityDisplayName(display);
    EXPECT_EQ(drawn.stats.value("patches"), byZBuffer.stats.value("patches"));
  }
}

// A new camera on the same scene draws the last solution again, as a new
// solution would be drawn; a changed colour solves again.
TEST(Radiosity, ANewCameraDrawsTheLastSolutionAgain) {
  Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box-measured.yaml");
  RenderSettings settings = radiositySettings(scene, 0.0f);
  settings.width = settings.height = 48;
  const RadiosityRenderer radiosity;
  RenderObserver observer;
  const RenderResult first = radiosity.render(scene, settings, observer);
  scene.camera.position += Vec3(60.0f, 40.0f, 0.0f);
  const RenderResult moved = radiosity.render(scene, settings, observer);
  const RenderResult afresh = RadiosityRenderer().render(scene, settings, observer);
  EXPECT_EQ(shareDiffering(moved.image, afresh.image), 0.0);
  EXPECT_LT(moved.stats.value("solve_seconds"), 0.5 * first.stats.value("solve_seconds"));
  for (Material& material : scene.materials)
    if (material.name == "white") material.color *= 0.5f;
  const RenderResult darker = radiosity.render(scene, settings, observer);
  EXPECT_GT(shareDiffering(darker.image, moved.image), 0.2);
}

class RecordingObserver final : public RenderObserver {
 public:
  StepRecorder* stepRecorder() override { return &recorder; }
  StepRecorder recorder;
};

double valueOf(const Step& step, std::string_view name) {
  for (const auto& [key, value] : step.values)
    if (key == name) return value;
  return -1.0;
}

// The steps of solving come before the display's: the mesh, then every
// shot, the lamp's first, the residual falling, the image drawn after the
// first shot.
TEST(Radiosity, TellsEveryShotInItsSteps) {
  const Scene scene =
      loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box-measured.yaml");
  RenderSettings settings = radiositySettings(scene, 150.0f);
  settings.width = 40;
  settings.height = 30;
  RecordingObserver observer;
  const RenderResult result = RadiosityRenderer().render(scene, settings, observer);
  const std::vector<Step> steps = observer.recorder.allSteps();
  ASSERT_FALSE(steps.empty());
  EXPECT_EQ(steps.front().kind, "mesh");
  EXPECT_EQ(valueOf(steps.front(), "patches"), result.stats.value("patches"));
  std::vector<const Step*> shots;
  for (const Step& step : steps)
    if (step.kind == "shot") shots.push_back(&step);
  ASSERT_EQ(static_cast<double>(shots.size()), result.stats.value("shots"));
  ASSERT_EQ(steps[1].kind, "shot");  // before the display's steps
  const RadiosityMesh mesh = meshForRadiosity(scene, settings);
  const Patch& firstShooter =
      mesh.patchMesh.patches[static_cast<std::size_t>(valueOf(*shots[0], "shooter"))];
  EXPECT_EQ(scene.materials[firstShooter.material].name, "light");
  EXPECT_FALSE(shots[0]->shapes.empty());
  EXPECT_EQ(shots[0]->writes.size(), static_cast<std::size_t>(40 * 30));
  EXPECT_TRUE(shots[2]->writes.empty());  // the third: not a power of two
  // By the hemicube, the first shooter's five images come before the shots,
  // their delta form factors summing to what the lamp sees of the room.
  settings.radiosity.formFactors = FormFactorMethod::Hemicube;
  settings.radiosity.hemicubeSize = 32;
  RecordingObserver hemicubeObserver;
  RadiosityRenderer().render(scene, settings, hemicubeObserver);
  const std::vector<Step> hemicubeSteps = hemicubeObserver.recorder.allSteps();
  ASSERT_GT(hemicubeSteps.size(), 2u);
  EXPECT_EQ(hemicubeSteps[1].kind, "hemicube");
  EXPECT_EQ(hemicubeSteps[1].writes.size(), static_cast<std::size_t>(40 * 30));
  EXPECT_GT(valueOf(hemicubeSteps[1], "form_factors_sum"), 0.5);
  EXPECT_LE(valueOf(hemicubeSteps[1], "form_factors_sum"), 1.0 + 1e-6);
  EXPECT_EQ(hemicubeSteps[2].kind, "shot");
  // The light still to pass on falls, shot after shot, to the residual.
  EXPECT_LT(valueOf(*shots.back(), "residual"), 0.1 * valueOf(*shots.front(), "residual"));
  EXPECT_LE(result.stats.value("residual"), settings.radiosity.residual);
}

class CancellingObserver final : public RenderObserver {
 public:
  bool cancelled() const override { return true; }
};

// A cancelled render stops solving, and its solution, cut short, is not
// the one the next render of the scene draws.
TEST(Radiosity, ACancelledSolutionIsNotKept) {
  const Scene scene =
      loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/cornell-box-measured.yaml");
  RenderSettings settings = radiositySettings(scene, 0.0f);
  settings.width = settings.height = 48;
  const RadiosityRenderer radiosity;
  CancellingObserver cancelling;
  const RenderResult cancelled = radiosity.render(scene, settings, cancelling);
  EXPECT_EQ(cancelled.stats.value("shots"), 0.0);
  RenderObserver observer;
  const RenderResult whole = radiosity.render(scene, settings, observer);
  EXPECT_GT(whole.stats.value("shots"), 0.0);
  EXPECT_LE(whole.stats.value("residual"), settings.radiosity.residual);
}

}  // namespace
}  // namespace rise
