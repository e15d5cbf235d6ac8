// Radiosity's patches: the surfaces whose light is solved, each made of one
// or more elements (Cohen, Greenberg, Immel and Brock, "An efficient
// radiosity approach for realistic image synthesis", 1986). A large face is
// cut into elements about a patch's size, and each is its own patch; the
// small triangles of a model are gathered, neighbours facing about the same
// way, into patches about that size, so that the form factors, N x N
// numbers for N patches, stay few however finely a model is tessellated.
// The light between patches is solved once; each element then shows its
// patch's light from the other patches with its own direct light, so that
// the shadows of the lights keep the elements' detail.
#pragma once

#include <optional>
#include <vector>

#include "radiosity/elements.hpp"

namespace rise {

struct Patch {
  std::vector<int> elements;  // into ElementMesh::elements
  // The centre of the element nearest the patch's mean point: a point on the
  // surface, where the rays of its form factors leave from.
  Vec3 centre{0.0f};
  Vec3 normal{0.0f};  // unit, the mean of its elements' weighed by their areas
  float area = 0.0f;  // the sum of its elements'
  // The area it shows along its normal: its area where it is flat, less
  // where it curves.
  float facingArea = 0.0f;
  int material = 0;
  bool twoSided = true;  // as its elements (Element::twoSided)
  // A patch of one element when gathered: that triangle, which its form
  // factors see, however finely meshing then cuts it.
  std::optional<std::array<Vec3, 3>> triangle;
};

struct PatchMesh {
  std::vector<Patch> patches;
  std::vector<int> patchOf;  // by element
};

// The elements of `mesh` gathered into patches of about `side`: an element
// whose longest side is under half of it is gathered with those of the same
// shape and material, facing the same way (the axis nearest its normal, and
// which way along it), in the same cube of `side` of the world; any other is
// a patch alone.
PatchMesh gatherPatches(const ElementMesh& mesh, float side);

// The patches meshElements(tessellated, side) then gatherPatches(..., side)
// would make, known without making them.
std::uint64_t patchCount(const TessellatedScene& tessellated, float side);

// The axis nearest a normal and which way along it, 0 to 5 (+x, -x, +y, -y,
// +z, -z): how the elements a patch gathers face the same way.
int facingOf(const Vec3& normal);

// Whether an element's front is its patch's front (else its back).
bool facesAsItsPatch(const Element& element, const Patch& patch);

}  // namespace rise
