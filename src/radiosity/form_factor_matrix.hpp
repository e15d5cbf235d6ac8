// The form factors between every two of radiosity's patches, found one of
// two ways (RadiositySettings::formFactors), and kept whole, N x N numbers
// for N patches, so that both solvers solve the very same equations:
//   rays: from each patch's centre to every other patch in closed form
//     (form_factors.hpp), times what a ray between their centres lets
//     through (Wallace, Elmquist and Haines 1989): one visibility ray for
//     each pair, both form factors from it;
//   hemicube: every patch's elements drawn onto a hemicube over each side
//     of each patch (hemicube.hpp), which finds the form factors to all the
//     others at once, with what hides them (Cohen and Greenberg 1985).
#pragma once

#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "radiosity/hemicube.hpp"
#include "radiosity/meshing.hpp"
#include "ray/scene_intersector.hpp"

namespace rise {

// The elements as the hemicube draws them, each its patch's.
std::vector<HemicubeTriangle> hemicubeTriangles(const ElementMesh& elements,
                                                const PatchMesh& patches);

class FormFactorMatrix {
 public:
  // `blockers`: the elements as a scene rays meet; `offset`: how far off a
  // surface its rays and hemicubes leave from.
  FormFactorMatrix(const RadiosityMesh& mesh, const SceneIntersector& blockers,
                   const RadiositySettings& settings, const Workers& workers, float offset);

  // The form factor from patch `to` to patch `from`: the share of the
  // hemisphere over `to`'s side facing `from` that `from` covers, projected
  // onto its base, and so the share of `from`'s light that `to` gathers.
  float operator()(std::size_t to, std::size_t from) const { return values_[to * count_ + from]; }
  // The side of patch `of` (kFrontSide, kBackSide) that faces `towards`.
  int sideFacing(std::size_t of, std::size_t towards) const {
    return sideFacing_[of * count_ + towards];
  }

  std::uint64_t visibilityRays() const { return visibilityRays_; }
  std::uint64_t hemicubeTexels() const { return hemicubeTexels_; }

 private:
  void findByRays(const SceneIntersector& blockers, float offset);
  void findByHemicubes(int resolution, float offset);
  float& value(std::size_t to, std::size_t from) { return values_[to * count_ + from]; }
  std::uint8_t& side(std::size_t of, std::size_t towards) {
    return sideFacing_[of * count_ + towards];
  }

  const PatchMesh& patches_;
  const ElementMesh& elements_;
  const Workers& workers_;
  std::size_t count_;
  std::vector<float> values_;             // by receiver, then source
  std::vector<std::uint8_t> sideFacing_;  // by patch, then the patch it faces
  std::uint64_t visibilityRays_ = 0, hemicubeTexels_ = 0;
};

}  // namespace rise
