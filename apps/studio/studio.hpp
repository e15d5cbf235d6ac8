// RISE Studio: one window in which a scene is opened or typed in, edited,
// previewed, rendered with any algorithm and compared. Each panel is drawn
// by its own file (scene_panel.cpp, text_panel.cpp, render_panel.cpp,
// compare_panel.cpp, help_panel.cpp); this class holds what they share and
// the actions that both the widgets and a scripted session (script.hpp)
// perform.
#pragma once

#include <imgui.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "file_browser.hpp"
#include "image_view.hpp"
#include "render/step_recorder.hpp"
#include "render_job.hpp"
#include "reports/comparison_report.hpp"
#include "reports/step_replay.hpp"
#include "session.hpp"
#include "texture.hpp"
#include "viewport.hpp"

namespace rise::studio {

// The panels are laid out for a window of 1600 x 1000 pixels; in another,
// the layout is scaled, so that every panel lies within the window.
inline constexpr float kLaidOutWidth = 1600.0f, kLaidOutHeight = 1000.0f;
// Places the panel about to begin where the layout puts it, the first time
// only (a user's moves are kept).
void placeAtFirst(ImVec2 position, ImVec2 size);

// The render panel's render: the job while it runs, then its result.
struct RenderView {
  std::unique_ptr<RenderJob> job;
  std::optional<RenderResult> result;
  std::string algorithm;  // of the result
  Image shown;            // the pixels finished so far
  Texture texture;
  std::string buffer;  // "" for the image, else the buffer shown
  Texture bufferTexture;
  ImageViewState view;
  ImageViewShown shownAt;  // where the view put the image last frame
};

// The step player: the steps an algorithm recorded, the image as it stood
// after the current one, its overlays.
struct StepPlayer {
  std::string algorithm;
  std::vector<Step> steps;
  std::uint64_t notDetailed = 0;
  Image finalImage;  // the render's, for the pixels steps say are settled
  Color background{0.0f};
  int current = -1;                    // -1: before the first step
  std::unique_ptr<StepReplay> replay;  // the image after the current step
  bool showDepth = false;              // the depth buffer instead of the image
  Texture texture;
  ImageViewState view;
  bool playing = false;
  float stepsPerSecond = 10.0f;
  double due = 0.0;           // steps owed to the playing clock
  bool bringForward = false;  // to its tab, once
};

// The ray trees of the pixel last clicked in a ray-traced image.
struct PixelInspection {
  std::unique_ptr<RenderJob> job;
  glm::ivec2 pixel{0};
  std::string algorithm;
  std::shared_ptr<const Scene> scene;  // the scene it was traced in
  Color pixelColor{0.0f};              // the render's colour there
  std::vector<RayTree> trees;
  int sample = 0;
  bool bringForward = false;  // the 3D view, where its rays are drawn, once
};

// The compare panel: the algorithms chosen, rendered one after the other.
struct Comparison {
  std::vector<std::string> chosen;
  // The visible-surface algorithms draw shadow maps, as `rise compare` has
  // them; unticked, the shadows of the Render panel.
  bool comparedShadows = true;
  std::shared_ptr<const Scene> scene;  // the scene it was rendered from
  std::vector<std::string> pending;
  std::unique_ptr<RenderJob> job;
  std::vector<ComparedRender> renders;
  std::vector<Texture> textures;
  ImageViewState view;        // shared: the images zoom and pan together
  int first = 0, second = 1;  // the two whose difference is shown
  Texture difference;
  double largestDifference = 0.0;
  int differenceOf[2] = {-1, -1};  // the renders the difference image was made of
};

class Studio {
 public:
  explicit Studio(const std::filesystem::path& scene);

  // Declares one frame's widgets. Returns false once the user has quit.
  bool frame(bool closeRequested);

  // What the widgets do, for the scripted session too.
  void open(const std::filesystem::path& path);  // asks first about unsaved changes
  bool saveScene(const std::filesystem::path& path);
  bool editValue(const std::string& path, const std::string& yaml, bool continuing = false);
  bool removeEntry(const std::string& path);
  bool copyEntry(const std::string& path);
  bool addItem(const std::string& listPath, const std::string& yaml);
  bool applyText(const std::string& text);
  void select(const std::string& path) { selection_ = path; }
  bool chooseAlgorithm(const std::string& name);
  void startRender();
  void cancelRender();
  void startComparison(const std::vector<std::string>& algorithms);
  // Traces the pixel again with the render panel's ray tracer, recording the
  // tree of rays of each of its samples.
  void inspectPixel(const glm::ivec2& pixel);
  void setRecordingSteps(bool on) { recordSteps_ = on; }
  // Whether each change to the scene (a camera orbited in the viewport)
  // renders it again: radiosity draws its last solution from the new camera.
  void setRenderingAsTheSceneChanges(bool on) { followScene_ = on; }
  void showStep(int step);
  bool saveImage(const std::filesystem::path& path);
  // The ray trees of the pixel clicked, as `rise inspect` prints them.
  bool saveRayTree(const std::filesystem::path& path);
  bool saveBuffer(const std::string& buffer, const std::filesystem::path& path);
  bool writeComparisonPage(const std::filesystem::path& directory);

  bool rendering() const {
    return render_.job != nullptr || comparison_.job != nullptr || inspection_.job != nullptr;
  }
  const StepPlayer& player() const { return player_; }
  const PixelInspection& inspection() const { return inspection_; }
  // Seconds from the last cancel until its render's thread had stopped.
  std::optional<double> lastCancelSeconds() const { return lastCancelSeconds_; }
  const Session& session() const { return session_; }
  const RenderView& renderView() const { return render_; }
  const Comparison& comparison() const { return comparison_; }
  const std::string& status() const { return status_; }

  // What a scripted session reaches directly: the render request, the
  // text pane's text as typed, and where each named widget was drawn last
  // frame (min x, min y, max x, max y).
  RenderRequest& request() { return request_; }
  bool replaceInText(const std::string& from, const std::string& to);
  std::optional<ImVec4> widget(const std::string& name) const;
  const std::map<std::string, ImVec4>& widgets() const { return widgets_; }

 private:
  void drawMenuBar();
  void drawScenePanel();
  void drawEntryTree(const std::string& path, const std::string& label);
  void drawFieldEditor();
  void drawField(const std::string& path, const std::string& key);
  void drawAddMenu(const std::string& listPath);
  void drawTextPanel();
  void drawViewportPanel();
  void drawSceneView();
  void drawRenderPanel();
  void drawRenderSettings(const AlgorithmDescription& algorithm);
  void drawRenderImage();
  void drawPixelValues();
  void drawComparePanel();
  void drawCompareTable();
  void drawDifference();
  void drawHelpPanel();
  void drawSteps();
  void drawStepOverlay(const Step& step, const ImageViewShown& shown);
  void drawRayTreePanel();
  void drawRayNode(const RayTree& tree, int ray);
  void startPlayer(const RenderJob& job);
  void finishInspection();
  void drawUnsavedQuestion();
  void drawStatusBar();

  // The settings to render the scene with; none, and why noted, when there
  // is no scene or the request does not fit it.
  std::optional<RenderSettings> settingsToRender();
  void updateRenders();
  void finishComparisonStep();
  void askBeforeLeaving(std::function<void()> then);
  void track(const std::string& name);
  // Where the panel begun last lies, as "panel/NAME", for the scripts'
  // layout: a panel's place, whatever of it is scrolled.
  void trackPanel(const std::string& name);
  void note(std::string message) { status_ = std::move(message); }
  // Where a file the studio writes is offered first: the folder of the
  // last one written, at first the folder the studio was started in (not
  // the scene's: the examples are the repository's).
  std::filesystem::path outputFolder() const { return outputFolder_; }
  // Says that `file` was written, and offers its folder next; true.
  bool wrote(const std::filesystem::path& file) {
    outputFolder_ = file.parent_path();
    note("wrote " + file.string());
    return true;
  }
  std::shared_ptr<const Scene> sceneOrNull() const { return session_.scene(); }

  Session session_;
  RecentFiles recent_;
  FileBrowser browser_;
  std::string selection_;
  std::string dragging_;     // the field being dragged, whose changes make one edit
  std::string text_;         // the text pane's contents
  int textRevision_ = -1;    // the session revision the text pane shows
  bool textEdited_ = false;  // typed in since
  bool textFocused_ = false;
  int pendingCursor_ = -1;  // where to put the text pane's cursor next frame
  std::optional<std::function<void()>> afterUnsavedQuestion_;
  bool quit_ = false;

  std::string algorithm_{defaultRenderer(Use::Render).name()};
  RenderRequest request_;
  RenderView render_;
  int renderedRevision_ = -1;  // the session revision the render panel's render is of
  std::vector<std::unique_ptr<RenderJob>> stopping_;  // cancelled, their threads finishing
  std::optional<std::chrono::steady_clock::time_point> cancelledAt_;
  std::optional<double> lastCancelSeconds_;

  Comparison comparison_;
  bool recordSteps_ = false;
  bool followScene_ = false;
  StepPlayer player_;
  PixelInspection inspection_;
  Viewport viewport_;
  bool showHelp_ = false;
  std::string status_;
  std::filesystem::path outputFolder_ = std::filesystem::current_path();
  std::map<std::string, ImVec4> widgets_;
};

}  // namespace rise::studio
