// The menu bar, its keyboard shortcuts, and the help panel: each algorithm's
// description and citation from the registry, and the manual.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdlib>

#include "algorithms/registry.hpp"
#include "core/text.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

std::filesystem::path manualPage() { return std::filesystem::path(RISE_MANUAL_DIR) / "index.html"; }

// Opens the page in the user's browser, without waiting for it.
bool openInBrowser(const std::filesystem::path& page) {
  std::string quoted = "'";
  for (char c : page.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  return std::system(("xdg-open " + quoted + " >/dev/null 2>&1 &").c_str()) == 0;
}

}  // namespace

void Studio::drawMenuBar() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool typing = io.WantTextInput;
  const auto shortcut = [&](int key, bool shift = false) {
    return io.KeyCtrl && io.KeyShift == shift && ImGui::IsKeyPressed(key, false);
  };
  const std::filesystem::path here = session_.path();
  bool openFile = shortcut(GLFW_KEY_O), save = shortcut(GLFW_KEY_S),
       saveAs = shortcut(GLFW_KEY_S, true);
  bool undo = !typing && shortcut(GLFW_KEY_Z),
       redo = !typing && (shortcut(GLFW_KEY_Y) || shortcut(GLFW_KEY_Z, true));
  bool render = ImGui::IsKeyPressed(GLFW_KEY_F5, false);
  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::BeginMenu("File")) {
      openFile |= ImGui::MenuItem("Open scene...", "Ctrl+O");
      if (ImGui::BeginMenu("Open recent", !recent_.paths().empty())) {
        for (const std::filesystem::path& path : recent_.paths())
          if (ImGui::MenuItem(path.string().c_str())) open(path);
        ImGui::EndMenu();
      }
      save |= ImGui::MenuItem("Save scene", "Ctrl+S", false, session_.document() != nullptr);
      saveAs |= ImGui::MenuItem("Save scene as...", "Ctrl+Shift+S", false,
                                session_.document() != nullptr);
      ImGui::Separator();
      if (ImGui::MenuItem("Save image...", nullptr, false, render_.result.has_value()))
        browser_.show(FileBrowser::Purpose::Save, "Save the rendered image (.png, .ppm, .exr)",
                      outputFolder() / "render.png", [this](const auto& path) { saveImage(path); });
      if (ImGui::MenuItem("Save buffer...", nullptr, false, !render_.buffer.empty()))
        browser_.show(
            FileBrowser::Purpose::Save, "Save the " + render_.buffer + " buffer",
            outputFolder() / ("render." + render_.buffer + ".png"),
            [this, buffer = render_.buffer](const auto& path) { saveBuffer(buffer, path); });
      if (ImGui::MenuItem("Save ray tree...", nullptr, false, !inspection_.trees.empty()))
        browser_.show(FileBrowser::Purpose::Save, "Save the pixel's ray trees as text",
                      outputFolder() / "ray-tree.txt",
                      [this](const auto& path) { saveRayTree(path); });
      if (ImGui::MenuItem("Write comparison page...", nullptr, false, !comparison_.renders.empty()))
        browser_.show(FileBrowser::Purpose::Folder, "Write the comparison into a folder",
                      outputFolder() / "comparison",
                      [this](const auto& path) { writeComparisonPage(path); });
      ImGui::Separator();
      if (ImGui::MenuItem("Quit")) askBeforeLeaving([this] { quit_ = true; });
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
      undo |= ImGui::MenuItem("Undo", "Ctrl+Z", false, session_.canUndo());
      redo |= ImGui::MenuItem("Redo", "Ctrl+Y", false, session_.canRedo());
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Render")) {
      render |= ImGui::MenuItem("Render", "F5", false, session_.scene() != nullptr);
      if (ImGui::MenuItem("Cancel", nullptr, false, render_.job != nullptr)) cancelRender();
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
      ImGui::MenuItem("Algorithms", nullptr, &showHelp_);
      if (ImGui::MenuItem("Open the manual")) {
        if (!std::filesystem::exists(manualPage()))
          note("the manual is not built: cmake --build build --target manual builds it into " +
               manualPage().parent_path().string());
        else if (!openInBrowser(manualPage()))
          note("could not start a browser (xdg-open) for " + manualPage().string());
      }
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }
  if (openFile)
    browser_.show(FileBrowser::Purpose::Open, "Open a scene file (.yaml, .yml, .json)", here,
                  [this](const auto& path) { open(path); });
  if (save && session_.document() && !here.empty()) saveScene(here);
  if ((saveAs || (save && here.empty())) && session_.document())
    browser_.show(FileBrowser::Purpose::Save, "Save the scene as", here,
                  [this](const auto& path) { saveScene(path); });
  if (undo) session_.undo();
  if (redo) session_.redo();
  if (render) startRender();
}

void Studio::drawHelpPanel() {
  if (!showHelp_) return;
  ImGui::SetNextWindowSize({620, 520}, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Algorithms", &showHelp_)) {
    ImGui::End();
    return;
  }
  for (const Renderer* renderer : allRenderers()) {
    const AlgorithmDescription& algorithm = renderer->description();
    if (!ImGui::CollapsingHeader(std::string(algorithm.name).c_str(),
                                 algorithm.name == algorithm_ ? ImGuiTreeNodeFlags_DefaultOpen : 0))
      continue;
    std::vector<std::string_view> options, effects;
    for (Option option : algorithm.options)
      for (std::string_view flag : flagsOf(option)) options.push_back(flag);
    for (Effect effect : algorithm.effects) effects.push_back(toString(effect));
    ImGui::TextWrapped("%s", std::string(algorithm.summary).c_str());
    ImGui::TextWrapped("Citation: %s", std::string(algorithm.citation).c_str());
    ImGui::Text("Family: %s", std::string(toString(algorithm.family)).c_str());
    ImGui::TextWrapped("Buffers: %s", joined(algorithm.buffers).c_str());
    ImGui::TextWrapped("Options: %s", joined(options).c_str());
    ImGui::TextWrapped("Effects: %s", joined(effects).c_str());
  }
  ImGui::End();
}

}  // namespace rise::studio
