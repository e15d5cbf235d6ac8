// A scene file as an editor holds it: its text, which is what is saved and
// what the loader reads, and the tree of its YAML, in which an entry is found
// by its path, the keys and list positions that lead to it joined by '/'
// ("objects/1/sphere/radius"). Every edit makes a new document. A value is
// replaced in the text itself, so that everything else, comments included,
// stays as it was; adding or removing an entry writes the tree out afresh.
// Whether the text is a scene is the loader's to say (load()): an editor
// keeps an edit only when it loads, so that whatever it saves, and every
// value it accepts, the command line accepts too.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace rise {

// An edit that does not fit the document: a path that leads nowhere, a value
// that is not YAML. The message says which.
class DocumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SceneDocument {
 public:
  enum class Kind { Missing, Value, List, Map };

  // Parses `text`, the scene file `source` (which relative paths in it start
  // from). Throws SceneError, at its line and column, for text that is not
  // YAML.
  SceneDocument(std::string text, std::string source);

  const std::string& text() const { return text_; }
  const std::string& source() const { return source_; }

  // The scene the text describes. Throws SceneError.
  Scene load() const;

  Kind kind(std::string_view path) const;
  std::vector<std::string> keys(std::string_view mapPath) const;  // in the document's order
  int size(std::string_view listPath) const;
  std::string value(std::string_view path) const;  // a value's text; "" for a list or a map
  // The 1-based line the entry starts at, for showing it in the text.
  int line(std::string_view path) const;

  // The document with the entry at `path` set to `yaml` (a value, a list,
  // a map), added to its map when missing. Throws DocumentError.
  SceneDocument withValue(std::string_view path, std::string_view yaml) const;
  // The document without the entry of a map or the item of a list at `path`.
  SceneDocument without(std::string_view path) const;
  // The document with a copy of the list item at `path` right after it.
  SceneDocument withCopy(std::string_view itemPath) const;
  // The document with `yaml` added at the end of the list at `listPath`, the
  // list made when missing.
  SceneDocument withItem(std::string_view listPath, std::string_view yaml) const;

  // Path helpers: "objects/1" and "sphere" give "objects/1/sphere".
  static std::string join(std::string_view path, std::string_view key);
  static std::string join(std::string_view path, int index);

 private:
  struct Tree;
  SceneDocument(std::string text, std::string source, std::shared_ptr<const Tree> tree);
  SceneDocument rewritten(const std::function<void(Tree&)>& change) const;

  std::string text_;
  std::string source_;
  std::shared_ptr<const Tree> tree_;
};

}  // namespace rise
