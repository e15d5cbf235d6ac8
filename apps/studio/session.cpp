#include "session.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/scene_error.hpp"

namespace rise::studio {
namespace {

Problem problemOf(const SceneError& error) { return {error.what(), error.line(), error.column()}; }

// The text of a file; nothing, with the problem set, when it cannot be read.
std::optional<std::string> readText(const std::filesystem::path& path, Problem& problem) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  if (file && !std::filesystem::is_directory(path)) text << file.rdbuf();
  if (!file || std::filesystem::is_directory(path)) {
    problem = {path.string() + ": cannot open the scene file (" +
               (std::filesystem::is_directory(path) ? std::string("it is a folder")
                                                    : std::string(std::strerror(errno))) +
               ")"};
    return std::nullopt;
  }
  return text.str();
}

}  // namespace

bool Session::open(const std::filesystem::path& path) {
  Problem problem;
  const std::optional<std::string> text = readText(path, problem);
  if (!text) {
    problem_ = problem;
    return false;
  }
  path_ = path;
  document_.reset();
  scene_.reset();
  ++revision_;
  history_.clear();
  current_ = 0;
  savedText_ = *text;
  problem_.reset();
  refusedText_.clear();
  if (setText(*text)) return true;
  return false;
}

bool Session::save(const std::filesystem::path& path) {
  if (!document_) {
    problem_ = Problem{"there is no scene to save: the text does not load"};
    return false;
  }
  const std::filesystem::path temporary = path.string() + ".saving";
  {
    std::ofstream file(temporary, std::ios::binary);
    file << document_->text();
    if (!file) {
      problem_ = Problem{path.string() + ": cannot write (" + std::strerror(errno) + ")"};
      std::filesystem::remove(temporary);
      return false;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    problem_ = Problem{path.string() + ": cannot write (" + error.message() + ")"};
    std::filesystem::remove(temporary);
    return false;
  }
  if (path_ != path) {
    // Relative paths in the scene now start from the new file's folder.
    path_ = path;
    show(document_->text());
  }
  savedText_ = document_->text();
  return true;
}

bool Session::edit(const std::function<SceneDocument(const SceneDocument&)>& change,
                   bool continuing) {
  if (!document_) return false;
  try {
    return accept(change(*document_), continuing, false);
  } catch (const SceneError& error) {
    refuse(problemOf(error), "");
  } catch (const DocumentError& error) {
    refuse({error.what()}, "");
  }
  return false;
}

bool Session::setText(const std::string& text) {
  try {
    return accept(SceneDocument(text, path_.string()), false, true);
  } catch (const SceneError& error) {
    refuse(problemOf(error), text);
  }
  return false;
}

bool Session::accept(SceneDocument document, bool continuing, bool typed) {
  try {
    auto scene = std::make_shared<const Scene>(document.load());
    if (document_ && document.text() == document_->text()) {
      problem_.reset();
      return true;
    }
    document_ = std::move(document);
    scene_ = std::move(scene);
    ++revision_;
    history_.resize(history_.empty() ? 0 : current_ + (continuing && current_ > 0 ? 0 : 1));
    history_.push_back(document_->text());
    current_ = history_.size() - 1;
    problem_.reset();
    refusedText_.clear();
    return true;
  } catch (const SceneError& error) {
    refuse(problemOf(error), typed ? document.text() : std::string());
  }
  return false;
}

void Session::refuse(Problem problem, std::string text) {
  problem_ = std::move(problem);
  refusedText_ = std::move(text);
}

void Session::show(const std::string& text) {
  try {
    SceneDocument document(text, path_.string());
    scene_ = std::make_shared<const Scene>(document.load());
    document_ = std::move(document);
    ++revision_;
    problem_.reset();
  } catch (const SceneError& error) {
    refuse(problemOf(error), text);
  }
}

void Session::undo() {
  if (!canUndo()) return;
  show(history_[--current_]);
}

void Session::redo() {
  if (!canRedo()) return;
  show(history_[++current_]);
}

bool Session::modified() const {
  return document_ ? document_->text() != savedText_
                   : !refusedText_.empty() && refusedText_ != savedText_;
}

}  // namespace rise::studio
