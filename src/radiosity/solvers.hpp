// Radiosity's two solvers of the equations between patches (radiosity.cpp
// tells the algorithm): progressive refinement (Cohen, Chen, Wallace and
// Greenberg, "A progressive refinement approach to fast radiosity image
// generation", SIGGRAPH 1988), which shoots, again and again, the light
// the patch holding the most has not yet passed on, so that the image is
// near right after a few shots; and Gauss-Seidel (Cohen and Greenberg,
// "The hemi-cube", SIGGRAPH 1985), which sweeps the equations, each
// patch's light computed again from the latest of the others. Both stop
// when the light still to pass on (or still changing) is under the
// residual's share of the light the sources give.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "radiosity/direct_light.hpp"
#include "radiosity/form_factor_matrix.hpp"

namespace rise {

// What solving found and what it cost.
struct RadiositySolution {
  std::vector<TwoSides> radiance;  // by element: the light leaving each side, the same every way
  int iterations = 0;              // shots, or sweeps of Gauss-Seidel
  double residual = 0.0;           // the light not yet passed on, over the sources'
  std::uint64_t formFactors = 0;
  std::uint64_t elementsCut = 0;  // by adaptive subdivision
  std::uint64_t visibilityRays = 0;
  std::uint64_t hemicubeTexels = 0;  // that showed a patch, by the hemicube
  std::uint64_t shadowRays = 0;      // to the lights of the classic model
};

// One shot or sweep, as a watcher is told it.
struct SolverIteration {
  int number = 0;  // from 1
  // The shooter and its side (progressive refinement); the patches it gave
  // light to, or, for a sweep, whose light changed.
  std::size_t patch = 0;
  int side = kFrontSide;
  std::size_t receivers = 0;
  double power = 0.0;  // shot, over the sources' light
  // The light still to pass on when the shot was chosen, or that the sweep
  // changed, over the sources'.
  double residual = 0.0;
};

// Watches the solution as it goes: each iteration, and, where wanted, each
// element's light as it stands (`elementLight` computes it).
class SolverWatcher {
 public:
  virtual void onIteration(const SolverIteration& iteration,
                           const std::function<std::vector<TwoSides>()>& elementLight) = 0;

 protected:
  ~SolverWatcher() = default;
};

// The light of every element: its own (emission and the direct light of the
// classic lights) and what it reflects of the light its patch gathered,
// solved by the settings' solver to their residual.
RadiositySolution solveEquations(const Scene& scene, const RadiosityMesh& mesh,
                                 const FormFactorMatrix& formFactors,
                                 const DirectLight& directLight, const RadiositySettings& settings,
                                 const Workers& workers, SolverWatcher* watcher);

}  // namespace rise
