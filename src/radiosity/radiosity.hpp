// Radiosity (radiosity.cpp tells it).
#pragma once

#include <vector>

#include "radiosity/refinement.hpp"
#include "render/renderer.hpp"

namespace rise {

class RadiosityRenderer final : public Renderer {
 public:
  const AlgorithmDescription& description() const override;
  RenderNeeds needs(const Scene& scene, const RenderSettings& settings) const override;
  RenderResult render(const Scene& scene, const RenderSettings& settings,
                      RenderObserver& observer) const override;
};

// What solving found and what it cost.
struct RadiositySolution {
  std::vector<TwoSides> radiance;  // by element: the light leaving each side, the same every way
  int iterations = 0;              // shots, or sweeps of Gauss-Seidel
  double residual = 0.0;           // the light not yet passed on, over the sources'
  std::uint64_t formFactors = 0;
  std::uint64_t elementsCut = 0;  // by adaptive subdivision
  std::uint64_t visibilityRays = 0;
  std::uint64_t shadowRays = 0;  // to the lights of the classic model
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
