// The live preview: the scene's triangles (the same tessellation the
// visible-surface algorithms draw) lit by its lights on the graphics card,
// seen by a camera the user orbits (left drag), pans (right drag, or
// shift and left drag) and zooms (wheel) about the scene camera's look_at
// point. The lights are drawn as gizmos (a star at a light's point, an arrow
// along a directional light) and the selected object in outline.
#pragma once

#include <imgui.h>

#include <optional>
#include <vector>

#include "core/math.hpp"
#include "scene/scene.hpp"

namespace rise::studio {

// A line drawn in the scene: a ray of a pixel's tree.
struct SceneLine {
  Vec3 from, to;
  Vec3 colour;
};

// Where the user placed the camera, to be written back to the scene.
struct CameraPlacement {
  Vec3 position;
  Vec3 lookAt;
};

class Viewport {
 public:
  Viewport() = default;
  ~Viewport();
  Viewport(const Viewport&) = delete;
  Viewport& operator=(const Viewport&) = delete;

  // Draws `scene` (of session revision `revision`) in a `size` region, the
  // object `selected` (an index into its shapes, or -1) outlined. Returns the
  // camera's placement once the user has moved it and let go.
  std::optional<CameraPlacement> draw(const Scene& scene, int revision, int selected, ImVec2 size);
  // Lines drawn over the scene until others are given.
  void showLines(const std::vector<SceneLine>& lines);

 private:
  struct Orbit {
    Vec3 target{0.0f};
    float yaw = 0.0f, pitch = 0.0f, distance = 5.0f;
    Vec3 position() const;
  };
  void prepare();
  void rebuild(const Scene& scene);
  void resizeTarget(int width, int height);
  bool handleInput(const Vec3& up);
  void renderScene(const Scene& scene, int selected, int width, int height);

  unsigned program_ = 0;
  unsigned vertexArray_ = 0, triangles_ = 0, lines_ = 0, extraLines_ = 0;
  int extraLineVertices_ = 0;
  unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
  int targetWidth_ = 0, targetHeight_ = 0;
  int triangleVertices_ = 0, lineVertices_ = 0;
  std::vector<std::pair<int, int>> shapeVertices_;  // first vertex and count, per shape
  int revision_ = -1;
  Orbit orbit_;
  bool moved_ = false;
};

}  // namespace rise::studio
