#include "image_view.hpp"

#include <algorithm>
#include <cmath>

namespace rise::studio {

ImageViewShown drawImageView(const char* id, const Texture& texture, ImageViewState& state,
                             ImVec2 size) {
  size.x = std::max(size.x, 16.0f);
  size.y = std::max(size.y, 16.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  draw.AddRectFilled(origin, {origin.x + size.x, origin.y + size.y}, IM_COL32(30, 30, 34, 255));
  if (texture.empty()) return {};

  const float width = static_cast<float>(texture.width());
  const float height = static_cast<float>(texture.height());
  const float fit = std::min(size.x / width, size.y / height);
  float zoom = state.zoom > 0.0f ? state.zoom : fit;
  const ImGuiIO& io = ImGui::GetIO();
  // Where image point (u, v) lands on the screen, and back.
  const auto screenOf = [&](float u, float v, float z) {
    return ImVec2(origin.x + size.x * 0.5f + (u - state.centre.x) * width * z,
                  origin.y + size.y * 0.5f + (v - state.centre.y) * height * z);
  };
  if (hovered && io.MouseWheel != 0.0f) {
    const float u = state.centre.x + (io.MousePos.x - origin.x - size.x * 0.5f) / (width * zoom);
    const float v = state.centre.y + (io.MousePos.y - origin.y - size.y * 0.5f) / (height * zoom);
    const float zoomed = std::clamp(zoom * std::pow(1.25f, io.MouseWheel), fit * 0.25f, 64.0f);
    // Keep the point under the pointer where it is.
    state.centre.x = u - (io.MousePos.x - origin.x - size.x * 0.5f) / (width * zoomed);
    state.centre.y = v - (io.MousePos.y - origin.y - size.y * 0.5f) / (height * zoomed);
    state.zoom = zoom = zoomed;
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
    state.centre.x -= io.MouseDelta.x / (width * zoom);
    state.centre.y -= io.MouseDelta.y / (height * zoom);
    if (state.zoom == 0.0f) state.zoom = zoom;
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) state = {};

  draw.PushClipRect(origin, {origin.x + size.x, origin.y + size.y}, true);
  draw.AddImage(texture.handle(), screenOf(0, 0, zoom), screenOf(1, 1, zoom));
  draw.PopClipRect();
  ImageViewShown shown{screenOf(0, 0, zoom), zoom, std::nullopt, false};
  if (!hovered) return shown;
  const int x = static_cast<int>(std::floor((io.MousePos.x - shown.topLeft.x) / zoom));
  const int y = static_cast<int>(std::floor((io.MousePos.y - shown.topLeft.y) / zoom));
  if (x < 0 || y < 0 || x >= texture.width() || y >= texture.height()) return shown;
  shown.hovered = glm::ivec2(x, y);
  shown.clicked = ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
                  io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 9.0f;
  return shown;
}

}  // namespace rise::studio
