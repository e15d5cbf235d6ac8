// Radiosity, after Goral, Torrance, Greenberg and Battaile, "Modeling the
// interaction of light between diffuse surfaces" (SIGGRAPH 1984).
//
// Where every surface is diffuse, the light leaving a point is the same in
// every direction, and the rendering equation becomes a sum: cut the
// surfaces into small elements, each of one radiance L_i, and
//   L_i = Le_i + rho_i * sum over j of F_ij L_j,
// what element i emits, and what it reflects (its reflectance rho_i) of the
// light of every other element j, F_ij being the share of what leaves i that
// reaches j: the form factor, which depends on geometry alone. The light of
// the whole scene is found once, for every viewpoint, by solving these
// equations; any visible-surface algorithm then draws the lit elements with
// the light interpolated across them (Gouraud), from any camera, at once.
//
// The steps:
//   meshing: the scene's triangles cut into elements, and the elements
//     gathered into patches, between which the light is solved
//     (meshing.hpp);
//   form factors: from each patch's centre to every other patch, in closed
//     form with a ray for what hides them, or by a hemicube drawn around
//     each patch (form_factor_matrix.hpp);
//   direct light: each element lit by the lights of the classic model, with
//     shadow rays to points spread over each light (soft shadows of area
//     lights), its patch's light the mean of its elements';
//   solving, one of two ways: progressive refinement (Cohen, Chen, Wallace
//     and Greenberg, "A progressive refinement approach to fast radiosity
//     image generation", SIGGRAPH 1988) shoots, again and again, the light
//     the patch holding the most has not yet passed on to all the others,
//     so that the image is near right after a few shots; Gauss-Seidel
//     (Cohen and Greenberg, "The hemi-cube", SIGGRAPH 1985) sweeps the
//     equations, each L_i computed again from the latest of the others. Both
//     stop when the light still to pass on (or still changing) is under the
//     `--residual` share of the light the sources give;
//   display: each element's light, its own direct light and what it reflects
//     of the light its patch gathered, carried to its corners (each the mean
//     of the elements around it), and drawn by the z-buffer, or by another
//     of the visible-surface algorithms (--display). A new camera on the
//     same scene only draws the solution again.
//
// Every surface is taken to be diffuse, with the reflectance kd C of its
// material (what it lets through left out). A surface standing alone (a
// wall, a polygon) has two sides, each with a light of its own; the outside
// of a solid alone takes and gives light. Mirrors, glass and highlights are
// the ray tracers' (the two-pass method of Wallace, Cohen and Greenberg,
// SIGGRAPH 1987, would add them).
#include "radiosity/radiosity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "core/elapsed.hpp"
#include "core/text.hpp"
#include "radiosity/display.hpp"
#include "radiosity/fingerprint.hpp"
#include "radiosity/form_factor_matrix.hpp"
#include "radiosity/solution_steps.hpp"
#include "raster/visible_surface_renderer.hpp"
#include "ray/scene_intersector.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& RadiosityRenderer::description() const {
  static const AlgorithmDescription description{
      .name = "radiosity",
      .summary =
          "Goral's radiosity: the light between diffuse surfaces solved once, drawn by a "
          "visible-surface algorithm",
      .citation =
          "C. M. Goral, K. E. Torrance, D. P. Greenberg, B. Battaile, Modeling the interaction of "
          "light between diffuse surfaces, SIGGRAPH 1984; M. F. Cohen, D. P. Greenberg, The "
          "hemi-cube, SIGGRAPH 1985; M. F. Cohen, S. E. Chen, J. R. "
          "Wallace, D. P. Greenberg, A progressive refinement approach to fast radiosity image "
          "generation, SIGGRAPH 1988",
      .family = Family::Radiosity,
      .buffers = {"depth", "normal", "cost", "face"},
      // Its faces are all drawn: an element's back may hold light of its own.
      .options = {Option::Tessellation, Option::PlaneSize, Option::Accel, Option::Radiosity},
      .effects = {Effect::Shadows, Effect::SoftShadows, Effect::IndirectLight},
      // The steps of the algorithm that draws the solution.
      .looks = {Look::Steps},
      // The solution is the whole scene's, and each tile draws it whole.
      .tileStatistics = TileStatistics::WholeImage};
  return description;
}

namespace {

std::uint64_t formFactorBytes(std::uint64_t patches) { return patches * patches * sizeof(float); }

// A render's cancellation without its progress, which the display reports.
class Cancellation final : public Progress {
 public:
  explicit Cancellation(const RenderObserver& observer) : observer_(observer) {}
  bool cancelled() const override { return observer_.cancelled(); }

 private:
  const RenderObserver& observer_;
};

// `observer`, where not null, may cancel the solution, and its step
// recorder, where it has one, is told the mesh and each iteration.
SolvedScene solveMeshed(const Scene& scene, const RenderSettings& settings, RadiosityMesh mesh,
                        RenderObserver* observer) {
  SolvedScene solved{std::move(mesh), {}};
  const Scene elements = elementsAsScene(scene, solved.mesh.elementMesh);
  const SceneIntersector blockers(elements, settings.accel, settings.threads);
  std::optional<Cancellation> cancellation;
  if (observer) cancellation.emplace(*observer);
  const Workers workers =
      cancellation ? Workers(settings.threads, *cancellation) : Workers(settings.threads);
  StepRecorder* const steps = observer ? observer->stepRecorder() : nullptr;
  const float offset = 1e-4f * sceneSize(scene);
  const DirectLight directLight(scene, blockers, offset);
  const RefinementCounts refined = refineWhereTheLightChanges(solved.mesh, directLight, workers);
  const FormFactorMatrix formFactors(solved.mesh, blockers, settings.radiosity, workers, offset);
  std::optional<SolutionSteps> watcher;
  if (steps) watcher.emplace(*steps, scene, settings, solved.mesh, offset).recordMesh(refined);
  solved.solution = solveEquations(scene, solved.mesh, formFactors, directLight, settings.radiosity,
                                   workers, watcher ? &*watcher : nullptr);
  solved.solution.elementsCut = refined.elementsCut;
  solved.solution.shadowRays += refined.shadowRays;
  solved.mesh.elementMesh.triangles.vertexRadiance =
      vertexLight(solved.mesh.elementMesh, solved.solution.radiance);
  return solved;
}

}  // namespace

SolvedScene solveRadiosity(const Scene& scene, const RenderSettings& settings) {
  return solveMeshed(scene, settings, meshForRadiosity(scene, settings), nullptr);
}

std::shared_ptr<const SolvedScene> RadiosityRenderer::solved(const Scene& scene,
                                                             const RenderSettings& settings,
                                                             RenderObserver& observer) const {
  RadiosityMesh mesh = meshForRadiosity(scene, settings);
  const std::uint64_t fingerprint = fingerprintOf(scene, mesh, settings.radiosity);
  {
    const std::lock_guard lock(lastMutex_);
    if (last_ && lastFingerprint_ == fingerprint && !observer.stepRecorder()) return last_;
  }
  auto solution =
      std::make_shared<const SolvedScene>(solveMeshed(scene, settings, std::move(mesh), &observer));
  // A solution cut short is drawn by nobody, and kept for nobody.
  if (observer.cancelled()) return solution;
  const std::lock_guard lock(lastMutex_);
  last_ = solution;
  lastFingerprint_ = fingerprint;
  return solution;
}

RenderNeeds RadiosityRenderer::needs(const Scene& scene, const RenderSettings& settings) const {
  RenderNeeds needs = visibleSurfaceNeeds(scene, settings);
  const RadiosityMeshSize size = radiosityMeshSize(scene, settings);
  const std::uint64_t bytes = formFactorBytes(size.patches);
  needs.bytes += bytes;
  if (bytes > needs.bytes / 2) {
    needs.mostOfTheMemory = "the form factors between " + grouped(size.patches) + " patches";
    needs.toTakeLess = "larger patches (--patch-size)";
  }
  const double pairs = 0.5 * static_cast<double>(size.patches) * static_cast<double>(size.patches);
  needs.rays = pairs + static_cast<double>(size.elements) * 16.0 * scene.lights.size();
  return needs;
}

RenderResult RadiosityRenderer::render(const Scene& scene, const RenderSettings& settings,
                                       RenderObserver& observer) const {
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const SolvedScene> solvedScene = solved(scene, settings, observer);
  const RadiositySolution& solution = solvedScene->solution;
  const RadiosityMesh& mesh = solvedScene->mesh;
  const double solveSeconds = secondsSince(start);

  RenderResult result = drawSolution(scene, settings, observer, mesh.elementMesh.triangles);
  Stats& stats = result.stats;
  stats.add("patches", static_cast<double>(mesh.patchMesh.patches.size()));
  stats.add("elements", static_cast<double>(mesh.elementMesh.elements.size()));
  stats.add("elements_cut", static_cast<double>(solution.elementsCut));
  stats.add("form_factors", static_cast<double>(solution.formFactors));
  if (settings.radiosity.formFactors == FormFactorMethod::Hemicube)
    stats.add("hemicube_texels", static_cast<double>(solution.hemicubeTexels));
  else
    stats.add("visibility_rays", static_cast<double>(solution.visibilityRays));
  stats.add("shadow_rays", static_cast<double>(solution.shadowRays));
  stats.add(settings.radiosity.solver == RadiositySolver::GaussSeidel ? "sweeps" : "shots",
            solution.iterations);
  stats.add("residual", solution.residual);
  // The time this render spent solving: next to none where it drew the
  // solution of the render before it again.
  stats.add("solve_seconds", solveSeconds);
  return result;
}

}  // namespace rise
