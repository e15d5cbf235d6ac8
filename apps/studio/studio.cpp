#include "studio.hpp"

#include <imgui.h>

#include <cstdlib>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"
#include "render/buffer_images.hpp"

namespace rise::studio {

Studio::Studio(const std::filesystem::path& scene) {
  for (const Renderer* renderer : defaultComparison())
    comparison_.chosen.emplace_back(renderer->name());
  if (!scene.empty()) open(scene);
}

bool Studio::frame(bool closeRequested) {
  updateRenders();
  widgets_.clear();
  drawMenuBar();
  drawScenePanel();
  drawTextPanel();
  drawViewportPanel();
  drawRenderPanel();
  drawComparePanel();
  drawHelpPanel();
  drawRayTreePanel();
  browser_.draw(recent_);
  drawUnsavedQuestion();
  drawStatusBar();
  if (closeRequested) askBeforeLeaving([this] { quit_ = true; });
  return !quit_;
}

void Studio::track(const std::string& name) {
  if (!ImGui::IsItemVisible()) return;  // scrolled away: a click there would land elsewhere
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  widgets_[name] = {min.x, min.y, max.x, max.y};
}

void Studio::trackPanel(const std::string& name) {
  const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  widgets_["panel/" + name] = {position.x, position.y, position.x + size.x, position.y + size.y};
}

void placeAtFirst(ImVec2 position, ImVec2 size) {
  const ImVec2 window = ImGui::GetMainViewport()->Size;
  const ImVec2 scale(window.x / kLaidOutWidth, window.y / kLaidOutHeight);
  ImGui::SetNextWindowPos({position.x * scale.x, position.y * scale.y}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({size.x * scale.x, size.y * scale.y}, ImGuiCond_FirstUseEver);
}

std::optional<ImVec4> Studio::widget(const std::string& name) const {
  const auto found = widgets_.find(name);
  if (found == widgets_.end()) return std::nullopt;
  return found->second;
}

bool Studio::replaceInText(const std::string& from, const std::string& to) {
  const std::size_t at = text_.find(from);
  if (at == std::string::npos) return false;
  text_.replace(at, from.size(), to);
  textEdited_ = true;
  return true;
}

void Studio::askBeforeLeaving(std::function<void()> then) {
  if (session_.modified())
    afterUnsavedQuestion_ = std::move(then);
  else
    then();
}

void Studio::drawUnsavedQuestion() {
  if (afterUnsavedQuestion_ && !ImGui::IsPopupOpen("Unsaved changes"))
    ImGui::OpenPopup("Unsaved changes");
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    return;
  ImGui::Text("The scene %s has changes that are not saved.",
              session_.path().filename().string().c_str());
  const bool save = ImGui::Button("Save");
  track("Save changes");
  ImGui::SameLine();
  const bool discard = ImGui::Button("Discard");
  track("Discard changes");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  if (save || discard || cancel) {
    std::function<void()> then = std::move(*afterUnsavedQuestion_);
    afterUnsavedQuestion_.reset();
    ImGui::CloseCurrentPopup();
    if (discard || (save && saveScene(session_.path()))) then();
  }
  ImGui::EndPopup();
}

void Studio::open(const std::filesystem::path& path) {
  askBeforeLeaving([this, path] {
    const bool loaded = session_.open(path);
    if (!session_.path().empty() && session_.path() == path) recent_.add(path);
    selection_.clear();
    note(loaded ? "opened " + path.string() : session_.problem()->message);
  });
}

bool Studio::saveScene(const std::filesystem::path& path) {
  if (!session_.save(path)) {
    note(session_.problem()->message);
    return false;
  }
  recent_.add(path);
  note("saved " + path.string());
  return true;
}

bool Studio::editValue(const std::string& path, const std::string& yaml, bool continuing) {
  const bool done = session_.edit(
      [&](const SceneDocument& document) { return document.withValue(path, yaml); }, continuing);
  if (!done && session_.problem()) note(session_.problem()->message);
  return done;
}

bool Studio::removeEntry(const std::string& path) {
  const bool done =
      session_.edit([&](const SceneDocument& document) { return document.without(path); });
  if (done && selection_.starts_with(path)) selection_.clear();
  if (!done && session_.problem()) note(session_.problem()->message);
  return done;
}

bool Studio::copyEntry(const std::string& path) {
  const bool done =
      session_.edit([&](const SceneDocument& document) { return document.withCopy(path); });
  if (!done && session_.problem()) note(session_.problem()->message);
  return done;
}

bool Studio::addItem(const std::string& listPath, const std::string& yaml) {
  const bool done = session_.edit(
      [&](const SceneDocument& document) { return document.withItem(listPath, yaml); });
  if (done) selection_ = SceneDocument::join(listPath, session_.document()->size(listPath) - 1);
  if (!done && session_.problem()) note(session_.problem()->message);
  return done;
}

bool Studio::applyText(const std::string& text) {
  const bool done = session_.setText(text);
  if (done) {
    textEdited_ = false;
    note("the text loads: the scene is updated");
  } else if (session_.problem()) {
    note(session_.problem()->message);
  }
  return done;
}

bool Studio::chooseAlgorithm(const std::string& name) {
  if (findRenderer(name) == nullptr) {
    note("no algorithm is called '" + name + "'");
    return false;
  }
  algorithm_ = name;
  return true;
}

std::optional<RenderSettings> Studio::settingsToRender() {
  const std::shared_ptr<const Scene> scene = session_.scene();
  if (!scene) {
    note("there is no scene to render: open one, or fix the text");
    return std::nullopt;
  }
  try {
    return settingsFor(*scene, request_);
  } catch (const SettingsError& error) {
    note(error.what());
    return std::nullopt;
  }
}

void Studio::startRender() {
  const std::optional<RenderSettings> settings = settingsToRender();
  if (!settings) return;
  cancelRender();
  // The last image stays until the new one's pixels come over it.
  if (render_.shown.width() != settings->width || render_.shown.height() != settings->height) {
    render_.shown = Image(settings->width, settings->height);
    render_.texture.upload(render_.shown);
  }
  render_.job = std::make_unique<RenderJob>(
      *findRenderer(algorithm_), session_.scene(), *settings,
      recordSteps_ ? std::optional<StepBudget>(StepBudget{}) : std::nullopt);
  renderedRevision_ = session_.revision();
}

void Studio::cancelRender() {
  if (!render_.job) return;
  render_.job->cancel();
  stopping_.push_back(std::move(render_.job));
}

void Studio::updateRenders() {
  if (render_.job) {
    const PixelRect changed = render_.job->takeFinishedPixels(render_.shown);
    if (!changed.isEmpty()) render_.texture.update(render_.shown, changed);
    if (render_.job->finished()) {
      if (render_.job->succeeded()) {
        render_.result = render_.job->result();
        render_.algorithm = std::string(render_.job->renderer().name());
        render_.shown = render_.result->image;
        render_.texture.upload(render_.shown);
        render_.buffer.clear();
        if (render_.job->recorder()) startPlayer(*render_.job);
        note(render_.algorithm + ": rendered in " + std::to_string(render_.job->seconds()) + " s");
      } else {
        note(render_.job->renderer().name().data() + std::string(": ") + render_.job->failure());
      }
      render_.job.reset();
    } else if (renderedRevision_ != session_.revision() && session_.scene()) {
      startRender();  // the scene changed under the render
    }
  } else if (followScene_ && render_.result && renderedRevision_ != session_.revision() &&
             session_.scene()) {
    startRender();
  }
  std::erase_if(stopping_, [this](const std::unique_ptr<RenderJob>& job) {
    if (!job->finished()) return false;
    lastCancelSeconds_ = job->secondsToStop();
    return true;
  });
  if (comparison_.job && comparison_.job->finished()) finishComparisonStep();
  if (inspection_.job && inspection_.job->finished()) finishInspection();
}

bool Studio::saveImage(const std::filesystem::path& path) {
  if (!render_.result) {
    note("nothing is rendered yet");
    return false;
  }
  try {
    writeImage(render_.result->image, path);
  } catch (const std::exception& error) {
    note(error.what());
    return false;
  }
  return wrote(path);
}

bool Studio::saveBuffer(const std::string& buffer, const std::filesystem::path& path) {
  if (!render_.result || !render_.result->buffers.contains(buffer)) {
    note("the render has no '" + buffer + "' buffer");
    return false;
  }
  try {
    const Image& raw = render_.result->buffers.find(buffer)->second;
    if (path.extension() == ".exr")
      writeImage(raw, path, Encoding::Linear);
    else
      writeImage(visualizeBuffer(buffer, raw), path, Encoding::Linear);
  } catch (const std::exception& error) {
    note(error.what());
    return false;
  }
  return wrote(path);
}

void Studio::drawStatusBar() {
  const ImGuiViewport& screen = *ImGui::GetMainViewport();
  const float height = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos({screen.Pos.x, screen.Pos.y + screen.Size.y - height});
  ImGui::SetNextWindowSize({screen.Size.x, height});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {8, 2});
  // One line high: no taller than a line, as the windows' least size would
  // make it, its foot below the window's.
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, {1, 1});
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  trackPanel("status bar");
  widgets_["window"] = {screen.Pos.x, screen.Pos.y, screen.Pos.x + screen.Size.x,
                        screen.Pos.y + screen.Size.y};
  ImGui::TextUnformatted(status_.c_str());
  ImGui::End();
  ImGui::PopStyleVar(2);
}

}  // namespace rise::studio
