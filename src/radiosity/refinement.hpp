// Adaptive subdivision: the elements cut finer where the direct light
// changes fast across them, at the edges of shadows, so that a shadow is
// drawn sharper than its patches (Cohen, Greenberg, Immel and Brock, "An
// efficient radiosity approach for realistic image synthesis", 1986).
//
// An element is cut into four by its sides' midpoints where, between its
// corners and centre, the share of the lights' light that shadows leave
// differs by more than a fifth (and the light itself by more than a fiftieth
// of the scene's brightest): again on the four, down to a 32nd of the patch
// size. Light that falls off smoothly, unshadowed, is left to Gouraud
// shading, whose interpolation over uneven triangles would show them. Where an element is cut and
// its neighbour is not, the midpoint it made lies on the neighbour's side: a T-vertex, at which
// Gouraud shading would change its slope on one side of the edge and not on the other, a crack of
// light. So a neighbour is cut too where it would meet elements two cuts finer, or new corners on
// all three sides; and where it meets new corners on one or two sides, it is drawn as the two or
// three triangles that end at them, each still showing the element's light.
#pragma once

#include "radiosity/direct_light.hpp"
#include "radiosity/meshing.hpp"

namespace rise {

struct RefinementCounts {
  std::uint64_t elementsCut = 0;
  std::uint64_t shadowRays = 0;
};

// Cuts the elements of `mesh` as above, each new element in its parent's
// patch, and makes the faces drawn again.
RefinementCounts refineWhereTheLightChanges(RadiosityMesh& mesh, const DirectLight& light,
                                            const Workers& workers);

}  // namespace rise
