#include "radiosity/solvers.hpp"

#include <algorithm>

namespace rise {

namespace {

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
         const DirectLight& directLight, const RadiositySettings& settings, const Workers& workers,
         SolverWatcher* watcher)
      : scene_(scene),
        directLight_(directLight),
        elements_(mesh.elementMesh),
        patches_(mesh.patchMesh),
        formFactors_(formFactors),
        settings_(settings),
        workers_(workers),
        watcher_(watcher),
        count_(patches_.patches.size()) {
    for (const Patch& patch : patches_.patches)
      reflectance_.push_back(reflectanceOf(scene.materials[patch.material]));
  }

  RadiositySolution solve() {
    elementSources_ = sourceLight();
    const std::vector<TwoSides> sources = patchLight(elementSources_);
    if (settings_.solver == RadiositySolver::GaussSeidel)
      sweep(sources);
    else
      shoot(sources);
    solution_.radiance = elementLight();
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
  std::vector<TwoSides> elementLight() const {
    std::vector<TwoSides> light = elementSources_;
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
    for (std::size_t shot = 0; shot < mostShots && sourcePower > 0.0 && !workers_.cancelled();
         ++shot) {
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
      std::size_t receivers = 0;
      for (std::size_t i = 0; i < count_; ++i) {
        if (sideFacing(shooter, i) != shootingSide || formFactor(i, shooter) <= 0.0f) continue;
        const Color arriving = formFactor(i, shooter) * shotLight;
        const int side = sideFacing(i, shooter);
        gathered_[i][side] += arriving;
        unshot[i][side] += reflectance_[i] * arriving;
        ++receivers;
      }
      ++solution_.iterations;
      tell({solution_.iterations, shooter, shootingSide, receivers, most / sourcePower,
            solution_.residual});
    }
  }

  void tell(const SolverIteration& iteration) const {
    if (watcher_) watcher_->onIteration(iteration, [this] { return elementLight(); });
  }

  // Gauss-Seidel: each patch's light computed again from the equations,
  // with the latest light of the others, sweep after sweep, until a sweep
  // changes the light by less than the residual's share.
  void sweep(const std::vector<TwoSides>& sources) {
    std::vector<TwoSides> radiance = sources;
    gathered_.assign(count_, TwoSides{Color(0.0f), Color(0.0f)});
    const double sourcePower = powerOf(sources);
    constexpr int kMostSweeps = 1000;
    while (sourcePower > 0.0 && solution_.iterations < kMostSweeps && !workers_.cancelled()) {
      double changed = 0.0;
      std::size_t changing = 0;
      for (std::size_t i = 0; i < count_; ++i) {
        const TwoSides before = radiance[i];
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
        if (radiance[i] != before) ++changing;
      }
      ++solution_.iterations;
      solution_.residual = changed / sourcePower;
      tell({solution_.iterations, 0, kFrontSide, changing, solution_.residual, solution_.residual});
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
  SolverWatcher* watcher_;
  std::size_t count_;                     // of patches
  std::vector<TwoSides> elementSources_;  // by element: its light before any is passed on
  std::vector<Color> reflectance_;        // by patch
  std::vector<TwoSides> gathered_;        // by patch: the light reaching each side
  RadiositySolution solution_;
};

}  // namespace

RadiositySolution solveEquations(const Scene& scene, const RadiosityMesh& mesh,
                                 const FormFactorMatrix& formFactors,
                                 const DirectLight& directLight, const RadiositySettings& settings,
                                 const Workers& workers, SolverWatcher* watcher) {
  return Solver(scene, mesh, formFactors, directLight, settings, workers, watcher).solve();
}

}  // namespace rise
