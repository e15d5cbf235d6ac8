#include "radiosity/patches.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace rise {

namespace {

// What elements gathered into one patch share.
using PatchKey = std::tuple<int, int, bool, int, std::int64_t, std::int64_t, std::int64_t>;

std::int64_t cellOf(float coordinate, float side) {
  constexpr double kFarthestCell = 1e15;
  return static_cast<std::int64_t>(std::clamp(std::floor(static_cast<double>(coordinate) / side),
                                              -kFarthestCell, kFarthestCell));
}

PatchKey keyOf(int shape, int material, bool twoSided, const Vec3& centre, const Vec3& normal,
               float side) {
  return {shape,
          material,
          twoSided,
          facingOf(normal),
          cellOf(centre.x, side),
          cellOf(centre.y, side),
          cellOf(centre.z, side)};
}

// The sums over a patch's elements, then its centre and normal from them.
void completePatch(const ElementMesh& mesh, Patch& patch) {
  Vec3 weighedNormal(0.0f), weighedCentre(0.0f);
  for (const int e : patch.elements) {
    const Element& element = mesh.elements[e];
    patch.area += element.area;
    weighedNormal += element.area * element.normal;
    weighedCentre += element.area * element.centre;
  }
  const Element& first = mesh.elements[patch.elements.front()];
  patch.facingArea = glm::length(weighedNormal);
  patch.normal = patch.facingArea > 0.0f ? weighedNormal / patch.facingArea : first.normal;
  const Vec3 meanPoint = weighedCentre / patch.area;
  const auto distanceTo = [&](int e) { return glm::length(mesh.elements[e].centre - meanPoint); };
  patch.centre =
      mesh.elements[*std::min_element(patch.elements.begin(), patch.elements.end(),
                                      [&](int a, int b) { return distanceTo(a) < distanceTo(b); })]
          .centre;
  patch.material = first.material;
  patch.twoSided = first.twoSided;
  if (patch.elements.size() == 1)
    patch.triangle = cornersOf(mesh.triangles.vertices, first.vertices);
}

}  // namespace

int facingOf(const Vec3& normal) {
  const Vec3 size = glm::abs(normal);
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  return 2 * axis + (normal[axis] < 0.0f ? 1 : 0);
}

PatchMesh gatherPatches(const ElementMesh& mesh, float side) {
  PatchMesh gathered;
  gathered.patchOf.assign(mesh.elements.size(), 0);
  std::map<PatchKey, int> patchWithKey;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    const Element& element = mesh.elements[e];
    int patch = static_cast<int>(gathered.patches.size());
    if (longestSide(cornersOf(mesh.triangles.vertices, element.vertices)) < 0.5f * side) {
      const auto [found, isNew] =
          patchWithKey.try_emplace(keyOf(element.shape, element.material, element.twoSided,
                                         element.centre, element.normal, side),
                                   patch);
      patch = found->second;
      if (isNew) gathered.patches.emplace_back();
    } else {
      gathered.patches.emplace_back();
    }
    gathered.patches[patch].elements.push_back(e);
    gathered.patchOf[e] = patch;
  }
  for (Patch& patch : gathered.patches) completePatch(mesh, patch);
  return gathered;
}

std::uint64_t patchCount(const TessellatedScene& tessellated, float side) {
  std::uint64_t count = 0;
  std::map<PatchKey, int> gathered;
  for (const SceneFace& face : tessellated.faces) {
    const std::array<Vec3, 3> corners = cornersOf(tessellated.vertices, face.vertices);
    const Vec3 cross = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    if (!(glm::length(cross) > 0.0f)) continue;
    const auto cuts = static_cast<std::uint64_t>(cutsOfFace(corners, side));
    if (longestSide(corners) / static_cast<float>(cuts) >= 0.5f * side) {
      count += cuts * cuts;
      continue;
    }
    const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0f;
    gathered.try_emplace(
        keyOf(face.shape, face.material, !face.cullable, centre, glm::normalize(cross), side), 0);
  }
  return count + gathered.size();
}

bool facesAsItsPatch(const Element& element, const Patch& patch) {
  return glm::dot(element.normal, patch.normal) >= 0.0f;
}

}  // namespace rise
