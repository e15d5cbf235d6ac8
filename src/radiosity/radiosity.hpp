// Radiosity (radiosity.cpp tells it).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "radiosity/refinement.hpp"
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
  // the settings of radiosity are those it was solved from.
  std::shared_ptr<const SolvedScene> solved(const Scene& scene,
                                            const RenderSettings& settings) const;

  // The last solution, and the fingerprint of what it was solved from: a
  // new camera on the same scene (the studio's orbit) only draws it again.
  mutable std::mutex lastMutex_;
  mutable std::shared_ptr<const SolvedScene> last_;
  mutable std::uint64_t lastFingerprint_ = 0;
};

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
