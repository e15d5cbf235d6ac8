// The scene as the visible-surface algorithms see it: every shape covered
// with triangles in world space (Shape::tessellate), each triangle a face
// numbered in the order of the shapes.
#pragma once

#include <array>
#include <vector>

#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

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

struct TessellatedScene {
  std::vector<SurfaceVertex> vertices;
  std::vector<SceneFace> faces;
};

// Tessellates every shape of the scene; planes become squares centred under
// the camera.
TessellatedScene tessellateScene(const Scene& scene, const TessellationSettings& settings);

}  // namespace rise
