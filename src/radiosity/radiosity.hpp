// Radiosity (radiosity.cpp tells it).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "radiosity/refinement.hpp"
#include "radiosity/solvers.hpp"
#include "render/renderer.hpp"

namespace rise {

struct SolvedScene;

class RadiosityRenderer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;

 private:
  // The scene's solution: the last one again where the scene, its mesh and
  // the settings of radiosity are those it was solved from, and the
  // observer wants no steps of solving it; it may cancel the solution.
  std::shared_ptr<const SolvedScene> solved(const Scene& scene, const RenderSettings& settings,
                                            RenderObserver& observer) const;

  // The last solution, and the fingerprint of what it was solved from: a
  // new camera on the same scene (the studio's orbit) only draws it again.
  mutable std::mutex lastMutex_;
  mutable std::shared_ptr<const SolvedScene> last_;
  mutable std::uint64_t lastFingerprint_ = 0;
};

struct SolvedScene {
  RadiosityMesh mesh;  // its elements' vertices' light set (vertexRadiance), ready to draw
  RadiositySolution solution;
};

// The scene tessellated as the settings ask and cut into elements, the
// light between them solved: the form factors between every two elements
// (each pair's visibility by a ray), the light of the classic lights on
// each element, then the equations.
SolvedScene solveRadiosity(const Scene& scene, const RenderSettings& settings);

}  // namespace rise
