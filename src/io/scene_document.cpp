#include "io/scene_document.hpp"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <optional>

#include "io/scene_error.hpp"
#include "io/scene_file.hpp"
#include "io/yaml_document.hpp"

namespace rise {

struct SceneDocument::Tree {
  YAML::Node root;
};

namespace {

// The text is read by libyaml first (io/yaml_document.hpp), the scene
// loader's parser, whose messages are located and in a writer's words, and
// which refuses what yaml-cpp 0.7 would parse without bound (a leading
// comma); yaml-cpp then builds the tree that the editor changes and writes.
std::vector<YAML::Node> parseYaml(std::string_view text, const std::string& sourceName) {
  try {
    parseYamlDocuments(text);
  } catch (const YamlError& error) {
    throw SceneError(sourceName, error.mark().line + 1, error.mark().column + 1, error.what());
  }
  try {
    return YAML::LoadAll(std::string(text));
  } catch (const YAML::ParserException& error) {
    throw SceneError(sourceName, error.mark.line + 1, error.mark.column + 1,
                     "invalid YAML: " + error.msg);
  }
}

std::vector<std::string> partsOf(std::string_view path) {
  std::vector<std::string> parts;
  while (!path.empty()) {
    const std::size_t slash = path.find('/');
    parts.emplace_back(path.substr(0, slash));
    path = slash == std::string_view::npos ? std::string_view() : path.substr(slash + 1);
  }
  return parts;
}

std::optional<int> indexIn(const YAML::Node& list, const std::string& part) {
  int index = -1;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
  if (error != std::errc() || end != part.data() + part.size() || index < 0 ||
      index >= static_cast<int>(list.size()))
    return std::nullopt;
  return index;
}

// The entry `part` of a map or a list; an undefined node when there is none
// (yaml-cpp's own stand-in for a missing key throws when asked its type).
YAML::Node childOf(const YAML::Node& node, const std::string& part) {
  const YAML::Node& parent = node;  // const: looking does not add entries
  YAML::Node child(YAML::NodeType::Undefined);
  if (parent.IsMap()) {
    if (const YAML::Node found = parent[part]; found.IsDefined()) child.reset(found);
  } else if (parent.IsSequence()) {
    if (const std::optional<int> index = indexIn(parent, part)) child.reset(parent[*index]);
  }
  return child;
}

// The nodes from the root to the entry at `path`, the last undefined when it
// is missing.
std::vector<YAML::Node> chainTo(const YAML::Node& root, std::string_view path) {
  std::vector<YAML::Node> chain{root};
  for (const std::string& part : partsOf(path)) {
    if (!chain.back().IsDefined()) break;
    chain.push_back(childOf(chain.back(), part));
  }
  return chain;
}

YAML::Node nodeAt(const YAML::Node& root, std::string_view path) {
  return chainTo(root, path).back();
}

std::string emitted(const YAML::Node& node) {
  YAML::Emitter out;
  out << node;
  return out.c_str();
}

YAML::Node parseValue(std::string_view yaml) {
  const std::vector<YAML::Node> documents = [&] {
    try {
      return parseYaml(yaml, "the value");
    } catch (const SceneError& error) {
      throw DocumentError(error.what());
    }
  }();
  if (documents.size() != 1 || documents[0].IsNull())
    throw DocumentError("'" + std::string(yaml) + "' is not one YAML value");
  return documents[0];
}

// A plain scalar is spelt in the text as its value: it can be replaced there.
bool isPlainScalarIn(const std::string& text, const YAML::Node& node) {
  const std::string& scalar = node.Scalar();
  const auto pos = static_cast<std::size_t>(node.Mark().pos);
  return node.IsScalar() && node.Tag() == "?" && !scalar.empty() && pos < text.size() &&
         text.compare(pos, scalar.size(), scalar) == 0;
}

// The text with the value `now` spelt where `old` is, one plain scalar at a
// time, last first so that earlier positions hold; nothing when `old` is not
// spelt so simply.
std::optional<std::string> splicedValue(std::string text, const YAML::Node& old,
                                        const YAML::Node& now) {
  std::vector<std::pair<YAML::Node, YAML::Node>> replacements;
  if (old.IsScalar() && now.IsScalar()) {
    replacements.emplace_back(old, now);
  } else if (old.IsSequence() && now.IsSequence() && old.size() == now.size()) {
    for (std::size_t i = old.size(); i-- > 0;) {
      if (!old[i].IsScalar() || !now[i].IsScalar()) return std::nullopt;
      replacements.emplace_back(old[i], now[i]);
    }
  } else {
    return std::nullopt;
  }
  for (const auto& [from, to] : replacements) {
    if (!isPlainScalarIn(text, from)) return std::nullopt;
    text.replace(static_cast<std::size_t>(from.Mark().pos), from.Scalar().size(), emitted(to));
  }
  return text;
}

// `list` with `item` inserted before position `at` (copied: the nodes are
// shared), or without the item at `at` when `item` is undefined.
YAML::Node listChanged(const YAML::Node& list, std::size_t at, const YAML::Node& item) {
  YAML::Node changed(YAML::NodeType::Sequence);
  changed.SetStyle(list.Style());
  for (std::size_t i = 0; i <= list.size(); ++i) {
    if (i == at && item.IsDefined()) changed.push_back(YAML::Clone(item));
    if (i < list.size() && !(i == at && !item.IsDefined())) changed.push_back(list[i]);
  }
  return changed;
}

[[noreturn]] void failNoEntry(std::string_view path) {
  throw DocumentError("the scene has no entry '" + std::string(path) + "'");
}

// Sets the entry at `path` of `root` to `value`, adding it to its map when
// missing.
void setEntry(YAML::Node& root, std::string_view path, const YAML::Node& value) {
  const std::vector<std::string> parts = partsOf(path);
  if (parts.empty()) failNoEntry(path);
  const std::size_t slash = path.rfind('/');
  YAML::Node parent = slash == std::string_view::npos ? root : nodeAt(root, path.substr(0, slash));
  if (parent.IsMap()) {
    parent[parts.back()] = value;
  } else if (parent.IsSequence() && indexIn(parent, parts.back())) {
    parent[*indexIn(parent, parts.back())] = value;
  } else {
    failNoEntry(path);
  }
}

std::pair<std::string, std::size_t> listAndIndex(const YAML::Node& root,
                                                 std::string_view itemPath) {
  const std::size_t slash = itemPath.rfind('/');
  if (slash == std::string_view::npos) failNoEntry(itemPath);
  const std::string listPath(itemPath.substr(0, slash));
  const YAML::Node list = nodeAt(root, listPath);
  const std::optional<int> index =
      list.IsSequence() ? indexIn(list, std::string(itemPath.substr(slash + 1))) : std::nullopt;
  if (!index) failNoEntry(itemPath);
  return {listPath, static_cast<std::size_t>(*index)};
}

}  // namespace

SceneDocument::SceneDocument(std::string text, std::string source)
    : text_(std::move(text)), source_(std::move(source)) {
  const std::vector<YAML::Node> documents = parseYaml(text_, source_);
  auto tree = std::make_shared<Tree>();
  tree->root = documents.empty() ? YAML::Node(YAML::NodeType::Map) : documents[0];
  tree_ = std::move(tree);
}

SceneDocument::SceneDocument(std::string text, std::string source, std::shared_ptr<const Tree> tree)
    : text_(std::move(text)), source_(std::move(source)), tree_(std::move(tree)) {}

Scene SceneDocument::load() const { return loadScene(text_, source_); }

SceneDocument::Kind SceneDocument::kind(std::string_view path) const {
  const YAML::Node node = nodeAt(tree_->root, path);
  if (!node.IsDefined()) return Kind::Missing;
  if (node.IsMap()) return Kind::Map;
  if (node.IsSequence()) return Kind::List;
  return Kind::Value;
}

std::vector<std::string> SceneDocument::keys(std::string_view mapPath) const {
  std::vector<std::string> keys;
  const YAML::Node map = nodeAt(tree_->root, mapPath);
  if (map.IsMap())
    for (const auto& entry : map) keys.push_back(entry.first.Scalar());
  return keys;
}

int SceneDocument::size(std::string_view listPath) const {
  const YAML::Node list = nodeAt(tree_->root, listPath);
  return list.IsSequence() ? static_cast<int>(list.size()) : 0;
}

std::string SceneDocument::value(std::string_view path) const {
  const YAML::Node node = nodeAt(tree_->root, path);
  return node.IsScalar() ? node.Scalar() : std::string();
}

int SceneDocument::line(std::string_view path) const {
  const YAML::Node node = nodeAt(tree_->root, path);
  return node.IsDefined() ? node.Mark().line + 1 : 0;
}

SceneDocument SceneDocument::rewritten(const std::function<void(Tree&)>& change) const {
  Tree tree{YAML::Clone(tree_->root)};
  change(tree);
  return SceneDocument(emitted(tree.root) + "\n", source_);
}

SceneDocument SceneDocument::withValue(std::string_view path, std::string_view yaml) const {
  const YAML::Node now = parseValue(yaml);
  const YAML::Node old = nodeAt(tree_->root, path);
  if (old.IsDefined()) {
    if (std::optional<std::string> text = splicedValue(text_, old, now)) {
      // The text as spliced must say what was meant, or the tree is written
      // out instead.
      SceneDocument spliced(std::move(*text), source_);
      if (emitted(nodeAt(spliced.tree_->root, path)) == emitted(now) &&
          spliced.keys("") == keys(""))
        return spliced;
    }
  }
  return rewritten([&](Tree& tree) { setEntry(tree.root, path, now); });
}

SceneDocument SceneDocument::without(std::string_view path) const {
  const std::vector<YAML::Node> chain = chainTo(tree_->root, path);
  if (chain.size() < 2 || !chain.back().IsDefined()) failNoEntry(path);
  if (chain[chain.size() - 2].IsSequence()) {
    const std::pair<std::string, std::size_t> item = listAndIndex(tree_->root, path);
    const std::string& listPath = item.first;
    const std::size_t index = item.second;
    return rewritten([&](Tree& tree) {
      setEntry(
          tree.root, listPath,
          listChanged(nodeAt(tree.root, listPath), index, YAML::Node(YAML::NodeType::Undefined)));
    });
  }
  const std::string key = partsOf(path).back();
  const std::size_t slash = path.rfind('/');
  const std::string mapPath(slash == std::string_view::npos ? "" : path.substr(0, slash));
  return rewritten([&](Tree& tree) {
    YAML::Node map = mapPath.empty() ? tree.root : nodeAt(tree.root, mapPath);
    map.remove(key);
  });
}

SceneDocument SceneDocument::withCopy(std::string_view itemPath) const {
  const std::pair<std::string, std::size_t> item = listAndIndex(tree_->root, itemPath);
  const std::string& listPath = item.first;
  const std::size_t index = item.second;
  return rewritten([&](Tree& tree) {
    const YAML::Node list = nodeAt(tree.root, listPath);
    setEntry(tree.root, listPath, listChanged(list, index + 1, list[index]));
  });
}

SceneDocument SceneDocument::withItem(std::string_view listPath, std::string_view yaml) const {
  const YAML::Node item = parseValue(yaml);
  const YAML::Node list = nodeAt(tree_->root, listPath);
  if (list.IsDefined() && !list.IsSequence())
    throw DocumentError("'" + std::string(listPath) + "' is not a list");
  return rewritten([&](Tree& tree) {
    const YAML::Node old = nodeAt(tree.root, listPath);
    setEntry(tree.root, listPath,
             old.IsDefined() ? listChanged(old, old.size(), item)
                             : listChanged(YAML::Node(YAML::NodeType::Sequence), 0, item));
  });
}

std::string SceneDocument::join(std::string_view path, std::string_view key) {
  return path.empty() ? std::string(key) : std::string(path) + "/" + std::string(key);
}

std::string SceneDocument::join(std::string_view path, int index) {
  return join(path, std::to_string(index));
}

}  // namespace rise
