#include "radiosity/form_factor_matrix.hpp"

#include <array>

#include "radiosity/direct_light.hpp"
#include "radiosity/form_factors.hpp"
#include "radiosity/hemicube.hpp"

namespace rise {

namespace {

// To a patch cut from a face, its triangle's form factor; to one gathered of
// many elements, that of a disc of the area it shows.
float formFactorTo(const Patch& from, const Patch& to) {
  if (!to.triangle)
    return formFactorToDisc(from.centre, from.normal, to.centre, to.normal, to.facingArea);
  return formFactorToTriangle(from.centre, from.normal, *to.triangle, to.normal);
}

// Whether the light of `from`'s side facing `to` may reach `to`: the inside
// of a solid neither gives nor takes light.
bool facesOutward(const Patch& patch, int side) { return patch.twoSided || side == kFrontSide; }

}  // namespace

std::vector<HemicubeTriangle> hemicubeTriangles(const ElementMesh& elements,
                                                const PatchMesh& patches) {
  std::vector<HemicubeTriangle> triangles;
  triangles.reserve(elements.elements.size());
  for (std::size_t e = 0; e < elements.elements.size(); ++e)
    triangles.push_back({cornersOf(elements.triangles.vertices, elements.elements[e].vertices),
                         patches.patchOf[e]});
  return triangles;
}

FormFactorMatrix::FormFactorMatrix(const RadiosityMesh& mesh, const SceneIntersector& blockers,
                                   const RadiositySettings& settings, const Workers& workers,
                                   float offset)
    : patches_(mesh.patchMesh),
      elements_(mesh.elementMesh),
      workers_(workers),
      count_(patches_.patches.size()),
      values_(count_ * count_, 0.0f),
      sideFacing_(count_ * count_, kFrontSide) {
  if (settings.formFactors == FormFactorMethod::Hemicube)
    findByHemicubes(settings.hemicubeSize, offset);
  else
    findByRays(blockers, offset);
}

// Each pair's visibility once, by one ray between their centres; both form
// factors from it, each to the side of the other that faces it. Row i is
// filled by task i alone, past the diagonal, and so is column i: no two
// tasks write one number.
void FormFactorMatrix::findByRays(const SceneIntersector& blockers, float offset) {
  visibilityRays_ = workers_.sumOverTasks<std::uint64_t>(
      static_cast<int>(count_), [&](int task, std::uint64_t& rays) {
        const auto i = static_cast<std::size_t>(task);
        const Patch& a = patches_.patches[i];
        IntersectionCounters counters;
        for (std::size_t j = i + 1; j < count_; ++j) {
          const Patch& b = patches_.patches[j];
          const int sideOfA = sideTowards(a.centre, a.normal, b.centre),
                    sideOfB = sideTowards(b.centre, b.normal, a.centre);
          if (!facesOutward(a, sideOfA) || !facesOutward(b, sideOfB)) continue;
          const float towardsB = formFactorTo(a, b), towardsA = formFactorTo(b, a);
          if (towardsB <= 0.0f && towardsA <= 0.0f) continue;
          ++rays;
          const Vec3 from = leaving(a.centre, a.normal, b.centre, offset),
                     to = leaving(b.centre, b.normal, a.centre, offset);
          const float through =
              luminance(blockers.transmittance({from, to - from}, 0.0f, 1.0f, counters));
          value(i, j) = towardsB * through;
          value(j, i) = towardsA * through;
          side(i, j) = static_cast<std::uint8_t>(sideOfA);
          side(j, i) = static_cast<std::uint8_t>(sideOfB);
        }
      });
}

// A hemicube over each side of each patch that gives and takes light, from
// just off its centre; each other patch takes the form factor of the side
// that sees more of it. Row i is filled by patch i's task alone. Then two
// patches see each other only where each one's hemicube saw the other, as
// with the rays' one ray a pair: a patch half hidden, whose light is one
// number for all of it, would otherwise give the light of its hidden part
// (a ceiling over a lamp) to those that see its other part.
void FormFactorMatrix::findByHemicubes(int resolution, float offset) {
  const std::vector<HemicubeTriangle> triangles = hemicubeTriangles(elements_, patches_);
  constexpr int kPatchesATask = 8;
  hemicubeTexels_ = workers_.sumOverTasks<std::uint64_t>(
      static_cast<int>((count_ + kPatchesATask - 1) / kPatchesATask),
      [&](int task, std::uint64_t& texels) {
        Hemicube hemicube(resolution);
        std::array<std::vector<float>, 2> bySide;
        const std::size_t end =
            std::min(count_, static_cast<std::size_t>(task + 1) * kPatchesATask);
        for (std::size_t i = static_cast<std::size_t>(task) * kPatchesATask; i < end; ++i) {
          const Patch& patch = patches_.patches[i];
          for (const int facing : {kFrontSide, kBackSide}) {
            bySide[facing].assign(count_, 0.0f);
            if (!facesOutward(patch, facing)) continue;
            const Vec3 normal = facing == kFrontSide ? patch.normal : -patch.normal;
            texels += hemicube.addFormFactors(patch.centre + offset * normal, normal, triangles,
                                              static_cast<int>(i), bySide[facing]);
          }
          for (std::size_t j = 0; j < count_; ++j) {
            const Patch& other = patches_.patches[j];
            const int facing =
                bySide[kBackSide][j] > bySide[kFrontSide][j] ? kBackSide : kFrontSide;
            side(i, j) = static_cast<std::uint8_t>(facing);
            if (facesOutward(other, sideTowards(other.centre, other.normal, patch.centre)))
              value(i, j) = bySide[facing][j];
          }
        }
      });
  workers_.forEachTask(static_cast<int>(count_), [&](int task) {
    const auto i = static_cast<std::size_t>(task);
    for (std::size_t j = i + 1; j < count_; ++j)
      if (value(i, j) <= 0.0f || value(j, i) <= 0.0f) value(i, j) = value(j, i) = 0.0f;
  });
}

}  // namespace rise
