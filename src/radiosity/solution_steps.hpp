// The steps of radiosity's solution, for `rise explain` and the studio's
// step player, before those of the algorithm that draws it: the mesh, then
// each shot or sweep in the solver's words, the patch that shot outlined,
// and the image as it stands drawn after the 1st, 2nd, 4th, 8th, ...; with
// the hemicube, the first shooter's five images of patch numbers.
#pragma once

#include "radiosity/meshing.hpp"
#include "radiosity/refinement.hpp"
#include "radiosity/solvers.hpp"
#include "raster/view_projection.hpp"
#include "render/renderer.hpp"

namespace rise {

class SolutionSteps final : public SolverWatcher {
 public:
  // `offset`: how far off a surface its hemicube is drawn from, as the
  // form factors' are.
  SolutionSteps(StepRecorder& steps, const Scene& scene, const RenderSettings& settings,
                const RadiosityMesh& mesh, float offset);

  void recordMesh(const RefinementCounts& refined);
  void onIteration(const SolverIteration& iteration,
                   const std::function<std::vector<TwoSides>()>& elementLight) override;

 private:
  void recordHemicube(std::size_t patch, int side);
  // The patch's elements on the screen, those wholly in front of the eye.
  std::vector<StepShape> outlineOf(std::size_t patch) const;
  // The image drawn from the elements' light, as pixels written.
  std::vector<PixelWrite> imageOf(const std::vector<TwoSides>& elementLight) const;

  StepRecorder& steps_;
  const Scene& scene_;
  const RenderSettings& settings_;
  const RadiosityMesh& mesh_;
  float offset_;
  ViewProjection view_;
};

}  // namespace rise
