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

#include "core/elapsed.hpp"
#include "core/text.hpp"
#include "radiosity/fingerprint.hpp"
#include "radiosity/form_factor_matrix.hpp"
#include "raster/area_subdivision.hpp"
#include "raster/depth_sort.hpp"
#include "raster/scanline.hpp"
#include "raster/z_buffer.hpp"
#include "ray/scene_intersector.hpp"
#include "render/render_limits.hpp"

namespace rise {

const AlgorithmDescription& RadiosityRenderer::description() const {
  static const AlgorithmDescription description{
      .name = "radiosity",
      .summary =
          "Goral's radiosity: the light between diffuse surfaces solved once, drawn by the "
          "z-buffer",
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

// The diffuse reflectance of a material, scaled down where a channel would
// pass 1, as no surface gives back more light than it receives.
Color reflectanceOf(const Material& material) {
  const Color rho = material.kd * (1.0f - material.transmission) * material.color;
  const float largest = maxComponent(rho);
  return largest > 1.0f ? rho / largest : rho;
}

class Solver {
 public:
  Solver(const Scene& scene, const RadiosityMesh& mesh, const FormFactorMatrix& formFactors,
         const DirectLight& directLight, const RadiositySettings& settings, const Workers& workers)
      : scene_(scene),
        directLight_(directLight),
        elements_(mesh.elementMesh),
        patches_(mesh.patchMesh),
        formFactors_(formFactors),
        settings_(settings),
        workers_(workers),
        count_(patches_.patches.size()) {
    for (const Patch& patch : patches_.patches)
      reflectance_.push_back(reflectanceOf(scene.materials[patch.material]));
  }

  RadiositySolution solve() {
    const std::vector<TwoSides> elementSources = sourceLight();
    const std::vector<TwoSides> sources = patchLight(elementSources);
    if (settings_.solver == RadiositySolver::GaussSeidel)
      sweep(sources);
    else
      shoot(sources);
    solution_.radiance = elementLight(elementSources);
    solution_.formFactors = count_ > 0 ? count_ * (count_ - 1) : 0;
    solution_.visibilityRays = formFactors_.visibilityRays();
    solution_.hemicubeTexels = formFactors_.hemicubeTexels();
    return std::move(solution_);
  }

 private:
  float formFactor(std::size_t to, std::size_t from) const { return formFactors_(to, from); }
  int sideFacing(std::size_t of, std::size_t towards) const {
    return formFactors_.sideFacing(of, towards);
  }
  const Patch& patch(std::size_t i) const { return patches_.patches[i]; }

  // What each side of each element gives off before any light is passed
  // between patches: its emission, and what it reflects of the classic
  // lights.
  std::vector<TwoSides> sourceLight() {
    const std::vector<Element>& elements = elements_.elements;
    std::vector<TwoSides> sources(elements.size());
    std::vector<std::uint64_t> rays(elements.size(), 0);
    workers_.forEachTask(static_cast<int>(elements.size()), [&](int task) {
      const auto e = static_cast<std::size_t>(task);
      const Element& element = elements[e];
      const Color& emission = scene_.materials[element.material].emission;
      sources[e] = directLight_.reflected(element.centre, element.normal, element.twoSided,
                                          reflectance_[patches_.patchOf[e]], rays[e]);
      sources[e][kFrontSide] += emission;
      if (element.twoSided) sources[e][kBackSide] += emission;
    });
    for (const std::uint64_t count : rays) solution_.shadowRays += count;
    return sources;
  }

  // The side of its patch an element's side is.
  int patchSide(std::size_t element, int side) const {
    const Element& of = elements_.elements[element];
    return facesAsItsPatch(of, patch(patches_.patchOf[element])) ? side : 1 - side;
  }

  // Each patch's light: the mean of its elements', weighed by their areas.
  std::vector<TwoSides> patchLight(const std::vector<TwoSides>& elementLight) const {
    std::vector<TwoSides> light(count_, TwoSides{Color(0.0f), Color(0.0f)});
    for (std::size_t e = 0; e < elementLight.size(); ++e) {
      const std::size_t p = patches_.patchOf[e];
      for (int side : {kFrontSide, kBackSide})
        light[p][patchSide(e, side)] +=
            elementLight[e][side] * (elements_.elements[e].area / patch(p).area);
    }
    return light;
  }

  // Each element's light: its own, and what it reflects of the light its
  // patch gathered from the others.
  std::vector<TwoSides> elementLight(const std::vector<TwoSides>& elementSources) const {
    std::vector<TwoSides> light = elementSources;
    for (std::size_t e = 0; e < light.size(); ++e) {
      const std::size_t p = patches_.patchOf[e];
      for (int side : {kFrontSide, kBackSide})
        light[e][side] += reflectance_[p] * gathered_[p][patchSide(e, side)];
    }
    return light;
  }

  double powerOf(const TwoSides& light, std::size_t i) const {
    return (static_cast<double>(luminance(light[kFrontSide])) + luminance(light[kBackSide])) *
           patch(i).area;
  }
  double powerOf(const std::vector<TwoSides>& light) const {
    double power = 0.0;
    for (std::size_t i = 0; i < count_; ++i) power += powerOf(light[i], i);
    return power;
  }

  // Progressive refinement: the side of a patch with the most light not yet
  // passed on gives it to every patch that side faces, each keeping what it
  // reflects of it as light of its own to pass on in turn.
  void shoot(const std::vector<TwoSides>& sources) {
    gathered_.assign(count_, TwoSides{Color(0.0f), Color(0.0f)});
    std::vector<TwoSides> unshot = sources;
    const double sourcePower = powerOf(sources);
    const std::size_t mostShots = 200 * std::max<std::size_t>(count_, 1);
    for (std::size_t shot = 0; shot < mostShots && sourcePower > 0.0; ++shot) {
      std::size_t shooter = 0;
      int shootingSide = kFrontSide;
      double most = -1.0, unshotPower = 0.0;
      for (std::size_t i = 0; i < count_; ++i)
        for (int side : {kFrontSide, kBackSide}) {
          const double power = static_cast<double>(luminance(unshot[i][side])) * patch(i).area;
          unshotPower += power;
          if (power > most) {
            most = power;
            shooter = i;
            shootingSide = side;
          }
        }
      solution_.residual = unshotPower / sourcePower;
      if (solution_.residual <= settings_.residual) break;
      const Color shotLight = unshot[shooter][shootingSide];
      unshot[shooter][shootingSide] = Color(0.0f);
      for (std::size_t i = 0; i < count_; ++i) {
        if (sideFacing(shooter, i) != shootingSide) continue;
        const Color arriving = formFactor(i, shooter) * shotLight;
        const int side = sideFacing(i, shooter);
        gathered_[i][side] += arriving;
        unshot[i][side] += reflectance_[i] * arriving;
      }
      ++solution_.iterations;
    }
  }

  // Gauss-Seidel: each patch's light computed again from the equations,
  // with the latest light of the others, sweep after sweep, until a sweep
  // changes the light by less than the residual's share.
  void sweep(const std::vector<TwoSides>& sources) {
    std::vector<TwoSides> radiance = sources;
    gathered_.assign(count_, TwoSides{Color(0.0f), Color(0.0f)});
    const double sourcePower = powerOf(sources);
    constexpr int kMostSweeps = 1000;
    while (sourcePower > 0.0 && solution_.iterations < kMostSweeps) {
      double changed = 0.0;
      for (std::size_t i = 0; i < count_; ++i) {
        TwoSides& gathered = gathered_[i];
        gathered = {Color(0.0f), Color(0.0f)};
        for (std::size_t j = 0; j < count_; ++j)
          gathered[sideFacing(i, j)] += formFactor(i, j) * radiance[j][sideFacing(j, i)];
        for (int side : {kFrontSide, kBackSide}) {
          const Color updated = sources[i][side] + reflectance_[i] * gathered[side];
          changed +=
              static_cast<double>(luminance(glm::abs(updated - radiance[i][side]))) * patch(i).area;
          radiance[i][side] = updated;
        }
      }
      ++solution_.iterations;
      solution_.residual = changed / sourcePower;
      if (solution_.residual <= settings_.residual) break;
    }
  }

  const Scene& scene_;
  const DirectLight& directLight_;
  const ElementMesh& elements_;
  const PatchMesh& patches_;
  const FormFactorMatrix& formFactors_;
  const RadiositySettings& settings_;
  const Workers& workers_;
  std::size_t count_;               // of patches
  std::vector<Color> reflectance_;  // by patch
  std::vector<TwoSides> gathered_;  // by patch: the light reaching each side
  RadiositySolution solution_;
};

}  // namespace

namespace {

SolvedScene solveMeshed(const Scene& scene, const RenderSettings& settings, RadiosityMesh mesh) {
  SolvedScene solved{std::move(mesh), {}};
  const Scene elements = elementsAsScene(scene, solved.mesh.elementMesh);
  const SceneIntersector blockers(elements, settings.accel, settings.threads);
  const Workers workers(settings.threads);
  const float offset = 1e-4f * sceneSize(scene);
  const DirectLight directLight(scene, blockers, offset);
  const RefinementCounts refined = refineWhereTheLightChanges(solved.mesh, directLight, workers);
  const FormFactorMatrix formFactors(solved.mesh, blockers, settings.radiosity, workers, offset);
  solved.solution =
      Solver(scene, solved.mesh, formFactors, directLight, settings.radiosity, workers).solve();
  solved.solution.elementsCut = refined.elementsCut;
  solved.solution.shadowRays += refined.shadowRays;
  solved.mesh.elementMesh.triangles.vertexRadiance =
      vertexLight(solved.mesh.elementMesh, solved.solution.radiance);
  return solved;
}

const VisibleSurfaceRenderer& displayOf(RadiosityDisplay display) {
  static const ZBufferRenderer zBuffer;
  static const ScanlineRenderer scanline;
  static const DepthSortRenderer depthSort;
  static const AreaSubdivisionRenderer areaSubdivision;
  switch (display) {
    case RadiosityDisplay::Scanline:
      return scanline;
    case RadiosityDisplay::DepthSort:
      return depthSort;
    case RadiosityDisplay::AreaSubdivision:
      return areaSubdivision;
    case RadiosityDisplay::ZBuffer:
      break;
  }
  return zBuffer;
}

}  // namespace

SolvedScene solveRadiosity(const Scene& scene, const RenderSettings& settings) {
  return solveMeshed(scene, settings, meshForRadiosity(scene, settings));
}

std::shared_ptr<const SolvedScene> RadiosityRenderer::solved(const Scene& scene,
                                                             const RenderSettings& settings) const {
  RadiosityMesh mesh = meshForRadiosity(scene, settings);
  const std::uint64_t fingerprint = fingerprintOf(scene, mesh, settings.radiosity);
  {
    const std::lock_guard lock(lastMutex_);
    if (last_ && lastFingerprint_ == fingerprint) return last_;
  }
  auto solution =
      std::make_shared<const SolvedScene>(solveMeshed(scene, settings, std::move(mesh)));
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
  const std::shared_ptr<const SolvedScene> solvedScene = solved(scene, settings);
  const RadiositySolution& solution = solvedScene->solution;
  const RadiosityMesh& mesh = solvedScene->mesh;
  const double solveSeconds = secondsSince(start);

  // The light is drawn as it was solved: no shadows of the display's own.
  RenderSettings display = settings;
  display.shadows = ShadowMethod::None;
  display.shading = Shading::Gouraud;
  RenderResult result =
      displayOf(settings.radiosity.display).renderTessellated(scene, display, observer, [&](float) {
        return mesh.elementMesh.triangles;
      });
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
