// The scene as the visible-surface algorithms see it: every shape covered
// with triangles in world space (Shape::tessellate), each triangle a face
// numbered in the order of the shapes.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/parallel.hpp"
#include "scene/scene.hpp"
#include "scene/tessellation.hpp"
#include "scene/textures/projected_mapping.hpp"
#include "scene/transform.hpp"

namespace rise {

struct SceneFace {
  std::array<int, 3> vertices;  // into TessellatedScene::vertices, counter-clockwise
  int shape;                    // into Scene::shapes
  int primitive;                // the shape's primitive the face lies on (Tessellation)
  int material;                 // into Scene::materials
  // The face is part of a closed surface around a solid, and the eye is
  // outside that solid: if it faces away from the eye, it is hidden.
  bool cullable;
};

// A shape's projected mapping (Tessellation::projection), placed in the
// world: the texture coordinates of each point seen on its facets come from
// the point itself, as those of the ray tracer's hits do.
class PlacedProjection {
 public:
  PlacedProjection(const ProjectedMapping& mapping, const Mat4& worldFromMapping)
      : mapping_(&mapping), placement_(worldFromMapping) {}

  // Sets the coordinates and tangents of a point of the facets, by its
  // position and normal.
  void mapOnto(SurfacePoint& surface) const;
  // How far the coordinates move from those of `surface` to those of
  // `position`, a nearby point of the same facet (one face of a box
  // mapping): the short way around where u wraps.
  Vec2 stepTo(const SurfacePoint& surface, const Vec3& position) const;

 private:
  const ProjectedMapping* mapping_;
  AffineMap placement_;
};

struct TessellatedScene {
  std::vector<SurfaceVertex> vertices;
  std::vector<SceneFace> faces;
  std::vector<std::optional<PlacedProjection>> projections;  // by shape
  // The light each vertex gives off, the same in every direction, on the
  // side its normal points to (front) and on the other (back), where it was
  // solved before the scene is drawn (radiosity/radiosity.hpp): the surfaces
  // then show it, interpolated across each face, in place of the
  // illumination model. Empty otherwise.
  std::array<std::vector<Color>, 2> vertexRadiance;
};

// Tessellates every shape of the scene; planes become squares centred under
// the camera. The faces are filled on the workers.
TessellatedScene tessellateScene(const Scene& scene, const TessellationSettings& settings,
                                 const Workers& workers);

}  // namespace rise
