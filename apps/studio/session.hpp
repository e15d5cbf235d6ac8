// The scene being edited: the last text that loaded (its document and its
// scene), the history of such texts for undo and redo, and the file it came
// from. An edit is kept only when the edited text loads, so that the scene
// shown, rendered and saved is always one the command line accepts; a
// refused edit leaves the last good scene and says why, in the loader's own
// words.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/scene_document.hpp"

namespace rise::studio {

// Why a text or an edit was refused: the loader's message, and where in the
// text it points (0 when nowhere in particular).
struct Problem {
  std::string message;
  int line = 0;
  int column = 0;
};

class Session {
 public:
  // Opens a scene file. Its text is kept even when it does not load, for
  // the user to fix: then there is no scene and problem() says why.
  bool open(const std::filesystem::path& path);
  // Writes the scene's text to `path`, which becomes the session's file.
  bool save(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  // The last text that loaded, and its scene; null before any did.
  const SceneDocument* document() const { return document_ ? &*document_ : nullptr; }
  const std::shared_ptr<const Scene>& scene() const { return scene_; }
  // Changes whenever the scene does.
  int revision() const { return revision_; }

  // Applies `change` to the document; false, with problem() set, when the
  // result does not load (or the change does not fit the document). A
  // `continuing` edit (a drag still under way) replaces the last one in the
  // history instead of adding to it, so that one undo takes the whole drag.
  bool edit(const std::function<SceneDocument(const SceneDocument&)>& change,
            bool continuing = false);
  // Replaces the whole text (the text pane's Apply).
  bool setText(const std::string& text);

  // The text that was refused last, or opened and did not load; and why.
  const std::optional<Problem>& problem() const { return problem_; }
  const std::string& refusedText() const { return refusedText_; }
  void dismissProblem() { problem_.reset(); }

  bool canUndo() const { return current_ > 0; }
  bool canRedo() const { return current_ + 1 < history_.size(); }
  void undo();
  void redo();

  // The scene differs from the file it was opened from or saved to.
  bool modified() const;

 private:
  // Keeps `document` when it loads; else refuses it, keeping its text for
  // the text pane when it came from there (`typed`).
  bool accept(SceneDocument document, bool continuing, bool typed);
  void refuse(Problem problem, std::string text);
  void show(const std::string& text);

  std::filesystem::path path_;
  std::optional<SceneDocument> document_;
  std::shared_ptr<const Scene> scene_;
  int revision_ = 0;
  std::vector<std::string> history_;
  std::size_t current_ = 0;
  std::string savedText_;
  std::optional<Problem> problem_;
  std::string refusedText_;
};

}  // namespace rise::studio
