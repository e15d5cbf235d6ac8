// The scene's YAML text, editable: Apply loads it, and a text that does not
// load is refused with the loader's message, shown under the line and column
// it points at, while the last good scene stays.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "io/text_position.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

int moveCursor(ImGuiInputTextCallbackData* data) {
  int& pending = *static_cast<int*>(data->UserData);
  if (pending >= 0) {
    data->CursorPos = data->SelectionStart = data->SelectionEnd =
        std::min(pending, data->BufTextLen);
    pending = -1;
  }
  return 0;
}

}  // namespace

void Studio::drawTextPanel() {
  placeAtFirst({0, 680}, {400, 300});
  ImGui::Begin("Scene text");
  trackPanel("scene text");
  // Asked anew after Apply and Revert, which may settle the problem.
  const auto textRefused = [this] { return session_.problem() && !session_.refusedText().empty(); };
  if (!textEdited_ && textRevision_ != session_.revision()) {
    text_ = textRefused() ? session_.refusedText()
                          : (session_.document() ? session_.document()->text() : std::string());
    textRevision_ = session_.revision();
  }
  const ImGuiIO& io = ImGui::GetIO();
  const bool apply = ImGui::Button("Apply") ||
                     (textFocused_ && io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_ENTER, false));
  track("Apply");
  ImGui::SameLine();
  if (ImGui::Button("Revert") && session_.document()) {
    text_ = session_.document()->text();
    textEdited_ = false;
    session_.dismissProblem();
    note("reverted to the scene as it was last loaded");
  }
  track("Revert");
  ImGui::SameLine();
  ImGui::TextDisabled(textEdited_ ? "edited: Apply (Ctrl+Enter) loads it" : "");
  if (apply) applyText(text_);

  float errorHeight = 0.0f;
  if (textRefused()) errorHeight = ImGui::GetTextLineHeightWithSpacing() * 5;
  if (!textEdited_ && textRefused()) text_ = session_.refusedText();
  if (pendingCursor_ >= 0) ImGui::SetKeyboardFocusHere();
  if (ImGui::InputTextMultiline(
          "##text", &text_, {-1, -1 - errorHeight},
          ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackAlways, moveCursor,
          &pendingCursor_))
    textEdited_ = true;
  textFocused_ = ImGui::IsItemActive();
  track("text");
  if (textRefused()) {
    const Problem& problem = *session_.problem();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", problem.message.c_str());
    ImGui::PopStyleColor();
    if (problem.line > 0) {
      // The line, and a caret under the column, as a compiler shows them.
      const std::string number = std::to_string(problem.line);
      ImGui::Text("%s | %s", number.c_str(), lineShown(text_, problem.line - 1).c_str());
      ImGui::Text(
          "%s | %s^", std::string(number.size(), ' ').c_str(),
          std::string(static_cast<std::size_t>(std::max(problem.column - 1, 0)), ' ').c_str());
      if (ImGui::SmallButton("Go to the error"))
        pendingCursor_ =
            static_cast<int>(offsetOfShown(text_, {problem.line - 1, problem.column - 1}));
    }
  }
  ImGui::End();
}

}  // namespace rise::studio
