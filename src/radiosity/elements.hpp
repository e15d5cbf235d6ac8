// Radiosity's mesh: the scene's surfaces cut into elements, small triangles
// over each of which the light leaving is taken to be the same, and the
// light of the elements carried to their corners for drawing.
#pragma once

#include <array>
#include <vector>

#include "core/color.hpp"
#include "raster/tessellated_scene.hpp"

namespace rise {

struct Element {
  std::array<int, 3> vertices;  // into the mesh's vertices, counter-clockwise
  Vec3 centre{0.0f};
  Vec3 normal{0.0f};  // unit, of the flat triangle
  float area = 0.0f;
  int material = 0;
  int shape = 0;
  // Whether light arrives and leaves on both sides, as on a wall standing
  // alone; else on the front alone, the outside of a solid.
  bool twoSided = true;
};

// An element's two sides: the front, where its normal points, and the back.
inline constexpr int kFrontSide = 0;
inline constexpr int kBackSide = 1;
using TwoSides = std::array<Color, 2>;

struct ElementMesh {
  // The faces drawn: a face for each element, in the same order, as meshing
  // makes them; after adaptive subdivision, an element's triangle or the
  // triangles it is drawn as (refinement.hpp).
  TessellatedScene triangles;
  std::vector<Element> elements;
};

// Each face of `tessellated` cut into n x n triangles alike, n the fewest that
// make their longest side at most `largestSide` (at most kMostCutsOfAFace).
// Faces of no area are left out.
ElementMesh meshElements(const TessellatedScene& tessellated, float largestSide);

inline constexpr int kMostCutsOfAFace = 64;

std::array<Vec3, 3> cornersOf(const std::vector<SurfaceVertex>& vertices,
                              const std::array<int, 3>& indices);
// The n of a face's n x n cut (meshElements).
int cutsOfFace(const std::array<Vec3, 3>& corners, float largestSide);
float longestSide(const std::array<Vec3, 3>& corners);

// The elements as triangles a ray can meet, in `scene`'s materials: one mesh
// for each material, so that a transparent one lets its share of light
// through. Visibility between elements is asked of them, not of the exact
// shapes, whose curved surfaces their flat triangles cut into.
Scene elementsAsScene(const Scene& scene, const ElementMesh& mesh);

// The elements a mesh would have, known without making it (a render's
// memory and time are worked out from it first).
std::uint64_t elementCount(const TessellatedScene& tessellated, float largestSide);

// The light at each vertex of the mesh, on each side: the mean, weighed by
// area, of the light of the elements of its material that meet at its point
// and face its way (within 45 degrees, either side), so that a floor's light
// does not run up the wall at the corner where they meet, nor a lamp's onto
// the ceiling around it, and Gouraud shading shows no seam between elements.
std::array<std::vector<Color>, 2> vertexLight(const ElementMesh& mesh,
                                              const std::vector<TwoSides>& elementLight);

}  // namespace rise
