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

// Draws `texture` in a `size` region; returns the image pixel under the
// pointer, if any.
std::optional<glm::ivec2> drawImageView(const char* id, const Texture& texture,
                                        ImageViewState& state, ImVec2 size);

}  // namespace rise::studio
