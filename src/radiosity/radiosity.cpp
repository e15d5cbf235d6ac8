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
//   meshing: the scene's triangles cut into elements (elements.hpp);
//   form factors: from each element's centre to every other element, by the
//     disc's closed form (form_factors.hpp), zero where a ray between their
//     centres is blocked: the shadows;
//   direct light: each element lit by the lights of the classic model, with
//     shadow rays to points spread over each light (soft shadows of area
//     lights);
//   solving, one of two ways: progressive refinement (Cohen, Chen, Wallace
//     and Greenberg, "A progressive refinement approach to fast radiosity
//     image generation", SIGGRAPH 1988) shoots, again and again, the light
//     that the element holding the most has not yet passed on to all the
//     others, so that the image is near right after a few shots; Gauss-Seidel
//     (Cohen and Greenberg, "The hemi-cube", SIGGRAPH 1985) sweeps the
//     equations, each L_i computed again from the latest of the others. Both
//     stop when the light still to pass on (or still changing) is under the
//     `--residual` share of the light the sources give;
//   display: the z-buffer draws the elements, each vertex showing the mean
//     light of the elements around it.
//
// Every surface is taken to be diffuse, with the reflectance kd C of its
// material (what it lets through left out). A surface standing alone (a
// wall, a polygon) has two sides, each with a light of its own; the outside
// of a solid alone takes and gives light. Mirrors, glass and highlights are
// the ray tracers' (the two-pass method of Wallace, Cohen and Greenberg,
// SIGGRAPH 1987, would add them). The form factors are kept, N x N numbers
// for N elements, so that the two solvers solve the very same equations.
#include "radiosity/radiosity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/elapsed.hpp"
#include "radiosity/form_factors.hpp"
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
          "light between diffuse surfaces, SIGGRAPH 1984; M. F. Cohen, S. E. Chen, J. R. "
          "Wallace, D. P. Greenberg, A progressive refinement approach to fast radiosity image "
          "generation, SIGGRAPH 1988",
      .family = Family::Radiosity,
      .buffers = {"depth", "normal", "cost", "face"},
      .options = {Option::Culling, Option::Tessellation, Option::PlaneSize, Option::Accel},
      .effects = {Effect::Shadows, Effect::SoftShadows, Effect::IndirectLight},
      // The solution is the whole scene's, and each tile draws it whole.
      .tileStatistics = TileStatistics::WholeImage};
  return description;
}

namespace {

// The bytes of the form factors of `elements` elements.
std::uint64_t formFactorBytes(std::uint64_t elements) {
  return elements * elements * sizeof(float);
}

// The diffuse reflectance of a material, scaled down where a channel would
// pass 1, as no surface gives back more light than it receives.
Color reflectanceOf(const Material& material) {
  const Color rho = material.kd * (1.0f - material.transmission) * material.color;
  const float largest = maxComponent(rho);
  return largest > 1.0f ? rho / largest : rho;
}

// A point just off the element's side that faces `towards`: rays leave from
// there, past the element itself.
Vec3 leaving(const Element& element, const Vec3& towards, float offset) {
  const float side = glm::dot(element.normal, towards - element.centre) >= 0.0f ? 1.0f : -1.0f;
  return element.centre + side * offset * element.normal;
}

class Solver {
 public:
  Solver(const Scene& scene, const ElementMesh& mesh, const SceneIntersector& blockers,
         const RadiositySettings& settings, const Workers& workers, float offset)
      : scene_(scene),
        mesh_(mesh),
        blockers_(blockers),
        settings_(settings),
        workers_(workers),
        offset_(offset),
        count_(mesh.elements.size()),
        formFactors_(count_ * count_, 0.0f),
        sideFacing_(count_ * count_, kFrontSide) {
    for (const Element& element : mesh.elements)
      reflectance_.push_back(reflectanceOf(scene.materials[element.material]));
  }

  RadiositySolution solve() {
    findFormFactors();
    const std::vector<TwoSides> sources = sourceLight();
    if (settings_.solver == RadiositySolver::GaussSeidel)
      sweep(sources);
    else
      shoot(sources);
    return std::move(solution_);
  }

 private:
  float& formFactor(std::size_t to, std::size_t from) { return formFactors_[to * count_ + from]; }
  // The side of element `of` that faces element `towards`.
  std::uint8_t& sideFacing(std::size_t of, std::size_t towards) {
    return sideFacing_[of * count_ + towards];
  }

  static int sideTowards(const Element& element, const Vec3& point) {
    return glm::dot(element.normal, point - element.centre) >= 0.0f ? kFrontSide : kBackSide;
  }

  // Each pair's visibility once, by one ray between their centres; both
  // form factors from it, each to the side of the other that faces it.
  // Row i is filled by task i alone, past the diagonal, and so is column i:
  // no two tasks write one number.
  void findFormFactors() {
    std::vector<std::uint64_t> rays(count_, 0);
    workers_.forEachTask(static_cast<int>(count_), [&](int task) {
      const auto i = static_cast<std::size_t>(task);
      const Element& a = mesh_.elements[i];
      IntersectionCounters counters;
      for (std::size_t j = i + 1; j < count_; ++j) {
        const Element& b = mesh_.elements[j];
        const int sideOfA = sideTowards(a, b.centre), sideOfB = sideTowards(b, a.centre);
        // The inside of a solid neither gives nor takes light.
        if ((!a.twoSided && sideOfA == kBackSide) || (!b.twoSided && sideOfB == kBackSide))
          continue;
        const float towardsB = formFactorTo(a, b), towardsA = formFactorTo(b, a);
        if (towardsB <= 0.0f && towardsA <= 0.0f) continue;
        ++rays[i];
        const Vec3 from = leaving(a, b.centre, offset_), to = leaving(b, a.centre, offset_);
        const float through =
            luminance(blockers_.transmittance({from, to - from}, 0.0f, 1.0f, counters));
        formFactor(i, j) = towardsB * through;
        formFactor(j, i) = towardsA * through;
        sideFacing(i, j) = static_cast<std::uint8_t>(sideOfA);
        sideFacing(j, i) = static_cast<std::uint8_t>(sideOfB);
      }
    });
    for (const std::uint64_t count : rays) solution_.visibilityRays += count;
    solution_.formFactors = count_ > 0 ? count_ * (count_ - 1) : 0;
  }

  float formFactorTo(const Element& from, const Element& to) const {
    const std::vector<SurfaceVertex>& vertices = mesh_.triangles.vertices;
    return formFactorToTriangle(
        from.centre, from.normal,
        {vertices[to.vertices[0]].position, vertices[to.vertices[1]].position,
         vertices[to.vertices[2]].position},
        to.normal);
  }

  // What each side of each element gives off before any light is passed
  // between elements: its emission, and what it reflects of the classic
  // lights, each light sampled at 4 x 4 points of its area (one, for a point
  // light, 16 times the same), which give irradiance pi times their colour.
  std::vector<TwoSides> sourceLight() {
    std::vector<TwoSides> sources(count_);
    std::vector<std::uint64_t> rays(count_, 0);
    constexpr int kSide = 4;
    workers_.forEachTask(static_cast<int>(count_), [&](int task) {
      const auto i = static_cast<std::size_t>(task);
      const Element& element = mesh_.elements[i];
      const Color& emission = scene_.materials[element.material].emission;
      TwoSides& given = sources[i];
      given = {emission, element.twoSided ? emission : Color(0.0f)};
      IntersectionCounters counters;
      for (const std::unique_ptr<Light>& light : scene_.lights)
        for (int sample = 0; sample < kSide * kSide; ++sample) {
          const Vec2 u((sample % kSide + 0.5f) / kSide, (sample / kSide + 0.5f) / kSide);
          const LightSample toLight = light->illuminate(element.centre, u);
          const int side = sideTowards(element, element.centre + toLight.toLight);
          const float cosine = std::abs(glm::dot(element.normal, toLight.toLight));
          if (!(cosine > 0.0f) || (!element.twoSided && side == kBackSide)) continue;
          const Vec3 from = leaving(element, element.centre + toLight.toLight, offset_);
          ++rays[i];
          given[side] +=
              reflectance_[i] * toLight.color * cosine *
              blockers_.transmittance({from, toLight.toLight}, 0.0f, toLight.distance, counters) /
              static_cast<float>(kSide * kSide);
        }
    });
    for (const std::uint64_t count : rays) solution_.shadowRays += count;
    return sources;
  }

  double powerOf(const TwoSides& light, std::size_t element) const {
    return (static_cast<double>(luminance(light[kFrontSide])) + luminance(light[kBackSide])) *
           mesh_.elements[element].area;
  }
  double powerOf(const std::vector<TwoSides>& light) const {
    double power = 0.0;
    for (std::size_t i = 0; i < count_; ++i) power += powerOf(light[i], i);
    return power;
  }

  // Progressive refinement: the side of an element with the most light not
  // yet passed on gives it to every element that side faces, each keeping
  // what it reflects of it as light of its own to pass on in turn.
  void shoot(const std::vector<TwoSides>& sources) {
    std::vector<TwoSides>& radiance = solution_.radiance;
    radiance = sources;
    std::vector<TwoSides> unshot = sources;
    const double sourcePower = powerOf(sources);
    const std::size_t mostShots = 200 * std::max<std::size_t>(count_, 1);
    for (std::size_t shot = 0; shot < mostShots && sourcePower > 0.0; ++shot) {
      std::size_t shooter = 0;
      int shootingSide = kFrontSide;
      double most = -1.0, unshotPower = 0.0;
      for (std::size_t i = 0; i < count_; ++i)
        for (int side : {kFrontSide, kBackSide}) {
          const double power =
              static_cast<double>(luminance(unshot[i][side])) * mesh_.elements[i].area;
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
        const Color gained = reflectance_[i] * formFactor(i, shooter) * shotLight;
        const int side = sideFacing(i, shooter);
        radiance[i][side] += gained;
        unshot[i][side] += gained;
      }
      ++solution_.iterations;
    }
  }

  // Gauss-Seidel: each element's light computed again from the equations,
  // with the latest light of the others, sweep after sweep, until a sweep
  // changes the light by less than the residual's share.
  void sweep(const std::vector<TwoSides>& sources) {
    std::vector<TwoSides>& radiance = solution_.radiance;
    radiance = sources;
    const double sourcePower = powerOf(sources);
    constexpr int kMostSweeps = 1000;
    while (sourcePower > 0.0 && solution_.iterations < kMostSweeps) {
      double changed = 0.0;
      for (std::size_t i = 0; i < count_; ++i) {
        TwoSides gathered{Color(0.0f), Color(0.0f)};
        for (std::size_t j = 0; j < count_; ++j)
          gathered[sideFacing(i, j)] += formFactor(i, j) * radiance[j][sideFacing(j, i)];
        for (int side : {kFrontSide, kBackSide}) {
          const Color updated = sources[i][side] + reflectance_[i] * gathered[side];
          changed += static_cast<double>(luminance(glm::abs(updated - radiance[i][side]))) *
                     mesh_.elements[i].area;
          radiance[i][side] = updated;
        }
      }
      ++solution_.iterations;
      solution_.residual = changed / sourcePower;
      if (solution_.residual <= settings_.residual) break;
    }
  }

  const Scene& scene_;
  const ElementMesh& mesh_;
  const SceneIntersector& blockers_;
  const RadiositySettings& settings_;
  const Workers& workers_;
  float offset_;
  std::size_t count_;
  std::vector<float> formFactors_;        // by receiver, then source
  std::vector<std::uint8_t> sideFacing_;  // by element, then the element it faces
  std::vector<Color> reflectance_;
  RadiositySolution solution_;
};

// The size of what the scene holds that has bounds (a plane has none).
float sceneSize(const Scene& scene) {
  Bounds3 bounds;
  for (const std::unique_ptr<Shape>& shape : scene.shapes)
    if (const Bounds3 shapeBounds = shape->bounds(); shapeBounds.isFinite())
      bounds.grow(shapeBounds);
  const float size = bounds.isEmpty() ? 0.0f : glm::length(bounds.extent());
  return size > 0.0f ? size : 1.0f;
}

// The scene's triangles, a plane's square at most four times the size of
// the rest: the light of elements far beyond would be solved for nothing.
TessellatedScene sceneTriangles(const Scene& scene, const RenderSettings& settings) {
  RenderSettings near = settings;
  near.planeSize = std::min(settings.planeSize, 4.0f * sceneSize(scene));
  return tessellateForRaster(scene, near);
}

// Without a patch size, a 24th of the scene's size, made larger until the
// elements are at most kMostElementsByDefault, or each triangle of the
// scene is one (a scene of many small triangles has no fewer).
constexpr std::uint64_t kMostElementsByDefault = 3000;

float elementSideOf(const Scene& scene, const RenderSettings& settings,
                    const TessellatedScene& triangles) {
  if (settings.radiosity.patchSize > 0.0f) return settings.radiosity.patchSize;
  const float size = sceneSize(scene);
  float side = size / 24.0f;
  while (side < size && elementCount(triangles, side) > kMostElementsByDefault) side *= 1.25f;
  return side;
}

}  // namespace

SolvedScene solveRadiosity(const Scene& scene, const RenderSettings& settings) {
  SolvedScene solved;
  const TessellatedScene triangles = sceneTriangles(scene, settings);
  solved.mesh = meshElements(triangles, elementSideOf(scene, settings, triangles));
  const Scene elements = elementsAsScene(scene, solved.mesh);
  const SceneIntersector blockers(elements, settings.accel, settings.threads);
  const Workers workers(settings.threads);
  const float offset = 1e-4f * sceneSize(scene);
  solved.solution =
      Solver(scene, solved.mesh, blockers, settings.radiosity, workers, offset).solve();
  solved.mesh.triangles.vertexRadiance = vertexLight(solved.mesh, solved.solution.radiance);
  return solved;
}

RenderNeeds RadiosityRenderer::needs(const Scene& scene, const RenderSettings& settings) const {
  RenderNeeds needs = visibleSurfaceNeeds(scene, settings);
  const TessellatedScene triangles = sceneTriangles(scene, settings);
  const std::uint64_t elements = elementCount(triangles, elementSideOf(scene, settings, triangles));
  const std::uint64_t bytes = formFactorBytes(elements);
  needs.bytes += bytes;
  if (bytes > needs.bytes / 2) {
    needs.mostOfTheMemory = "the form factors between " + std::to_string(elements) + " elements";
    needs.toTakeLess = "larger elements (--patch-size)";
  }
  const double pairs = 0.5 * static_cast<double>(elements) * static_cast<double>(elements);
  needs.rays = pairs + static_cast<double>(elements) * 16.0 * scene.lights.size();
  return needs;
}

RenderResult RadiosityRenderer::render(const Scene& scene, const RenderSettings& settings,
                                       RenderObserver& observer) const {
  const auto start = std::chrono::steady_clock::now();
  const SolvedScene solved = solveRadiosity(scene, settings);
  const RadiositySolution& solution = solved.solution;
  const ElementMesh& mesh = solved.mesh;
  const double solveSeconds = secondsSince(start);

  // The light is drawn as it was solved: no shadows of the display's own.
  RenderSettings display = settings;
  display.shadows = ShadowMethod::None;
  display.shading = Shading::Gouraud;
  RenderResult result = ZBufferRenderer().renderTessellated(scene, display, observer,
                                                            [&](float) { return mesh.triangles; });
  Stats& stats = result.stats;
  stats.add("elements", static_cast<double>(mesh.elements.size()));
  stats.add("form_factors", static_cast<double>(solution.formFactors));
  stats.add("visibility_rays", static_cast<double>(solution.visibilityRays));
  stats.add("shadow_rays", static_cast<double>(solution.shadowRays));
  stats.add(settings.radiosity.solver == RadiositySolver::GaussSeidel ? "sweeps" : "shots",
            solution.iterations);
  stats.add("residual", solution.residual);
  stats.add("solve_seconds", solveSeconds);
  return result;
}

}  // namespace rise
