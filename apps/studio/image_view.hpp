// An image shown zoomed and panned: the wheel zooms about the pointer, the
// left button drags it. Views that share one ImageViewState move together
// (the compare panel's side-by-side images).
#pragma once

#include <imgui.h>

#include <optional>

#include "core/math.hpp"
#include "texture.hpp"

namespace rise::studio {

struct ImageViewState {
  float zoom = 0.0f;          // screen pixels per image pixel; 0: fit the view
  ImVec2 centre{0.5f, 0.5f};  // the image point at the view's centre, in [0, 1]
};

// Where a view put its image, and what the pointer did there.
struct ImageViewShown {
  ImVec2 topLeft{0, 0};               // of the image's pixel (0, 0), on the screen
  float zoom = 1.0f;                  // screen pixels per image pixel
  std::optional<glm::ivec2> hovered;  // the image pixel under the pointer
  bool clicked = false;               // pressed and let go there without dragging

  ImVec2 onScreen(const Vec2& raster) const {
    return {topLeft.x + raster.x * zoom, topLeft.y + raster.y * zoom};
  }
};

// Draws `texture` in a `size` region.
ImageViewShown drawImageView(const char* id, const Texture& texture, ImageViewState& state,
                             ImVec2 size);

}  // namespace rise::studio
