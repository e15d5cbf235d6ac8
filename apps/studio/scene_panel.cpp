// The scene panel: the tree of the scene's entries (image, camera, ambient
// light, lights, materials, objects) and the fields of the one selected,
// each edited by typing or dragging, colours by a picker; and the viewport.
// Every change goes through Studio::editValue and friends, which keep it only
// when the scene still loads.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <charconv>
#include <cstdlib>
#include <utility>

#include "core/text.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

using Kind = SceneDocument::Kind;

// What a new object or light starts as; every value can be edited after.
const std::pair<const char*, const char*> kNewObjects[] = {
    {"sphere", "sphere: {center: [0, 1, 0], radius: 0.5, material: @}"},
    {"box", "box: {min: [-0.5, 0, -0.5], max: [0.5, 1, 0.5], material: @}"},
    {"cylinder",
     "cylinder: {base: [0, 0, 0], axis: [0, 1, 0], radius: 0.3, height: 1, material: @}"},
    {"cone", "cone: {base: [0, 0, 0], axis: [0, 1, 0], radius: 0.4, height: 1, material: @}"},
    {"plane", "plane: {point: [0, 0, 0], normal: [0, 1, 0], material: @}"},
    {"triangle", "triangle: {vertices: [[-1, 0, 0], [1, 0, 0], [0, 1.5, 0]], material: @}"},
    {"polygon", "polygon: {vertices: [[-1, 0, 0], [1, 0, 0], [1, 1, 0], [-1, 1, 0]], material: @}"},
};
const std::pair<const char*, const char*> kNewLights[] = {
    {"point", "point: {position: [0, 5, -3], color: [1, 1, 1]}"},
    {"directional", "directional: {direction: [0, -1, 0.5], color: [0.5, 0.5, 0.5]}"},
    {"rect",
     "rect: {corner: [-0.5, 4, -0.5], edge1: [1, 0, 0], edge2: [0, 0, 1], color: [1, 1, 1]}"},
    {"disk", "disk: {center: [0, 4, 0], normal: [0, -1, 0], radius: 0.5, color: [1, 1, 1]}"},
    {"sphere", "sphere: {center: [0, 4, 0], radius: 0.3, color: [1, 1, 1]}"},
};

std::optional<float> numberIn(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

// The shortest text that reads back as the same float.
std::string spelt(float value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::to_string(value);
}

std::string spelt(const float* values, int count) {
  std::string text;
  for (int i = 0; i < count; ++i) appendListed(text, ", ", spelt(values[i]));
  return "[" + text + "]";
}

// Keys whose three numbers are a colour, shown with a colour picker.
bool isColour(const std::string& key, const std::string& parentKey) {
  return key == "color" || key == "background" || key == "ambient" || parentKey == "colors";
}

std::string lastPart(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string parentOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
}

// The one key of a list item such as "- sphere: {...}", or "".
std::string kindOf(const SceneDocument& document, const std::string& itemPath) {
  const std::vector<std::string> keys = document.keys(itemPath);
  return keys.size() == 1 && document.kind(SceneDocument::join(itemPath, keys[0])) == Kind::Map
             ? keys[0]
             : "";
}

}  // namespace

void Studio::drawScenePanel() {
  placeAtFirst({0, 20}, {400, 660});
  ImGui::Begin("Scene");
  trackPanel("scene");
  const SceneDocument* document = session_.document();
  if (document == nullptr) {
    ImGui::TextWrapped(session_.path().empty()
                           ? "No scene: open one from the File menu (Ctrl+O)."
                           : "The scene file does not load: fix its text in the Scene text "
                             "panel, or open another file.");
    ImGui::End();
    return;
  }
  ImGui::TextUnformatted(session_.path().filename().string().c_str());
  if (session_.modified()) {
    ImGui::SameLine();
    ImGui::TextDisabled("(modified)");
  }
  ImGui::BeginChild("tree", {0, ImGui::GetContentRegionAvail().y * 0.55f}, true);
  for (const char* key : {"image", "camera", "ambient", "lights", "materials", "objects"})
    drawEntryTree(key, key);
  ImGui::EndChild();
  drawFieldEditor();
  ImGui::End();
}

void Studio::drawEntryTree(const std::string& path, const std::string& label) {
  const SceneDocument& document = *session_.document();
  const Kind kind = document.kind(path);
  const bool holdsEntries = path == "lights" || path == "objects" || path == "materials";
  if (!holdsEntries) {
    if (kind == Kind::Missing) {
      ImGui::TextDisabled("%s (not set)", label.c_str());
    } else {
      if (ImGui::Selectable(label.c_str(), selection_ == path)) selection_ = path;
      track("tree/" + path);
    }
    return;
  }
  const bool open = ImGui::TreeNodeEx(label.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
  ImGui::SameLine();
  if (ImGui::SmallButton(("+##" + path).c_str())) ImGui::OpenPopup(("add " + path).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add to %s", label.c_str());
  track("add/" + path);
  drawAddMenu(path);
  if (!open) return;
  if (kind == Kind::List) {
    for (int i = 0; i < document.size(path); ++i) {
      const std::string item = SceneDocument::join(path, i);
      const std::string itemKind = kindOf(document, item);
      const std::string material =
          itemKind.empty() ? "" : document.value(SceneDocument::join(item, itemKind + "/material"));
      const std::string text = std::to_string(i) + ": " + itemKind +
                               (material.empty() ? "" : " (" + material + ")") + "##" + item;
      if (ImGui::Selectable(text.c_str(), selection_ == item)) selection_ = item;
      track("tree/" + item);
    }
  } else if (kind == Kind::Map) {
    for (const std::string& name : document.keys(path)) {
      const std::string item = SceneDocument::join(path, name);
      if (ImGui::Selectable(name.c_str(), selection_ == item)) selection_ = item;
      track("tree/" + item);
    }
  }
  ImGui::TreePop();
}

void Studio::drawAddMenu(const std::string& listPath) {
  if (!ImGui::BeginPopup(("add " + listPath).c_str())) return;
  const std::vector<std::string> materials = session_.document()->keys("materials");
  const std::string material = materials.empty() ? "none" : materials.front();
  if (listPath == "materials") {
    static std::string name = "new-material";
    ImGui::InputText("name", &name);
    if (ImGui::Button("Add material"))
      editValue("materials/" + name, "{color: [0.8, 0.8, 0.8], ka: 0.1, kd: 0.8}");
  }
  for (const auto& [kind, yaml] : listPath == "objects"  ? std::span(kNewObjects)
                                  : listPath == "lights" ? std::span(kNewLights)
                                                         : std::span(kNewLights).first(0)) {
    if (!ImGui::MenuItem(kind)) continue;
    std::string text = yaml;
    if (const std::size_t at = text.find('@'); at != std::string::npos)
      text.replace(at, 1, material);
    addItem(listPath, text);
  }
  ImGui::EndPopup();
}

void Studio::drawFieldEditor() {
  const SceneDocument& document = *session_.document();
  if (selection_.empty() || document.kind(selection_) == Kind::Missing) {
    ImGui::TextDisabled("Select an entry to edit it.");
    return;
  }
  ImGui::TextUnformatted(selection_.c_str());
  const std::string parent = parentOf(selection_);
  const bool inList = document.kind(parent) == Kind::List;
  if (inList) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Duplicate")) copyEntry(selection_);
    track("Duplicate");
  }
  if (inList || parent == "materials") {
    ImGui::SameLine();
    if (ImGui::SmallButton("Remove")) removeEntry(selection_);
    track("Remove");
  }
  if (session_.problem() && session_.refusedText().empty())
    ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "Refused: %s",
                       session_.problem()->message.c_str());
  const std::string kind = inList ? kindOf(document, selection_) : "";
  const std::string fields = kind.empty() ? selection_ : SceneDocument::join(selection_, kind);
  ImGui::BeginChild("fields");
  if (document.kind(fields) == Kind::Map) {
    for (const std::string& key : document.keys(fields)) drawField(fields, key);
    static std::string newKey, newValue;
    ImGui::Separator();
    ImGui::SetNextItemWidth(100);
    ImGui::InputText("##new key", &newKey);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    ImGui::InputText("##new value", &newValue);
    ImGui::SameLine();
    if (ImGui::Button("Add key") && !newKey.empty() &&
        editValue(SceneDocument::join(fields, newKey), newValue)) {
      newKey.clear();
      newValue.clear();
    }
  } else {
    drawField(parentOf(fields), lastPart(fields));
  }
  ImGui::EndChild();
}

void Studio::drawField(const std::string& parent, const std::string& key) {
  const SceneDocument& document = *session_.document();
  const std::string path = SceneDocument::join(parent, key);
  const Kind kind = document.kind(path);
  ImGui::PushID(path.c_str());
  // A drag is one edit for undo: the changes after its first continue it.
  const auto changed = [&](const std::string& yaml) {
    editValue(path, yaml, dragging_ == path);
    dragging_ = path;
  };
  const auto finishDrag = [&] {
    if (dragging_ == path && !ImGui::IsItemActive()) dragging_.clear();
  };
  if (kind == Kind::Value) {
    std::string text = document.value(path);
    if (key == "material") {
      if (ImGui::BeginCombo(key.c_str(), text.c_str())) {
        for (const std::string& material : document.keys("materials"))
          if (ImGui::Selectable(material.c_str(), material == text)) editValue(path, material);
        ImGui::EndCombo();
      }
    } else if (const std::optional<float> number = numberIn(text)) {
      float value = *number;
      const float speed = std::max(0.001f, std::abs(value) * 0.01f);
      if (ImGui::DragFloat(key.c_str(), &value, speed, 0.0f, 0.0f, "%g")) changed(spelt(value));
      finishDrag();
    } else if (ImGui::InputText(key.c_str(), &text, ImGuiInputTextFlags_EnterReturnsTrue)) {
      editValue(path, text);
    }
    track(path);
  } else if (kind == Kind::List && document.size(path) == 3 &&
             numberIn(document.value(SceneDocument::join(path, 0))) &&
             numberIn(document.value(SceneDocument::join(path, 1))) &&
             numberIn(document.value(SceneDocument::join(path, 2)))) {
    float values[3];
    for (int i = 0; i < 3; ++i) values[i] = *numberIn(document.value(SceneDocument::join(path, i)));
    const bool edited = isColour(key, lastPart(parent))
                            ? ImGui::ColorEdit3(key.c_str(), values,
                                                ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)
                            : ImGui::DragFloat3(key.c_str(), values, 0.01f, 0.0f, 0.0f, "%g");
    if (edited) changed(spelt(values, 3));
    finishDrag();
    track(path);
  } else if (kind == Kind::List || kind == Kind::Map) {
    if (ImGui::TreeNode(key.c_str())) {
      if (kind == Kind::Map)
        for (const std::string& child : document.keys(path)) drawField(path, child);
      else
        for (int i = 0; i < document.size(path); ++i) drawField(path, std::to_string(i));
      ImGui::TreePop();
    }
  }
  if (document.kind(parent) == Kind::Map) {
    ImGui::SameLine(ImGui::GetContentRegionMax().x - 20);
    if (ImGui::SmallButton("x")) removeEntry(path);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove '%s'", key.c_str());
  }
  ImGui::PopID();
}

// The algorithm's steps share this window with the 3D view, each in a tab of
// its own: a student switches between them, and neither hides the other.
// A new recording brings its steps forward; a clicked pixel, the 3D view
// where its rays are drawn.
void Studio::drawViewportPanel() {
  placeAtFirst({400, 20}, {560, 440});
  ImGui::Begin("Viewport");
  trackPanel("viewport");
  if (player_.steps.empty()) {
    drawSceneView();
  } else if (ImGui::BeginTabBar("views")) {
    const auto selectedIf = [](bool& bringForward) {
      return std::exchange(bringForward, false) ? ImGuiTabItemFlags_SetSelected
                                                : ImGuiTabItemFlags_None;
    };
    const bool sceneView =
        ImGui::BeginTabItem("3D view", nullptr, selectedIf(inspection_.bringForward));
    track("tab/3D view");
    if (sceneView) {
      drawSceneView();
      ImGui::EndTabItem();
    }
    const bool steps = ImGui::BeginTabItem("Steps", nullptr, selectedIf(player_.bringForward));
    track("tab/Steps");
    if (steps) {
      drawSteps();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

void Studio::drawSceneView() {
  const std::shared_ptr<const Scene> scene = session_.scene();
  if (!scene) {
    ImGui::TextDisabled("No scene.");
    return;
  }
  int selected = -1;
  if (selection_.starts_with("objects/")) selected = std::atoi(selection_.substr(8).c_str());
  ImGui::TextDisabled(
      "drag: orbit   right drag: pan   wheel: zoom   (the camera is written to the scene)");
  const std::optional<CameraPlacement> placement =
      viewport_.draw(*scene, session_.revision(), selected, ImGui::GetContentRegionAvail());
  track("viewport");
  if (placement) {
    const float position[3] = {placement->position.x, placement->position.y, placement->position.z};
    const float lookAt[3] = {placement->lookAt.x, placement->lookAt.y, placement->lookAt.z};
    if (editValue("camera/position", spelt(position, 3)))
      editValue("camera/look_at", spelt(lookAt, 3), true);
  }
}

}  // namespace rise::studio
