// A YAML document as the scene loader reads it: a tree of maps, lists and
// scalars, each knowing the line and column where it starts, so that every
// message about a value can point at it. libyaml, the reference C parser
// (fuzzed for years), turns the text into events; this file builds the tree
// from them and turns the parser's complaints into located messages in the
// words of someone writing a scene.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/text_position.hpp"

namespace rise {

// Lists and maps nested deeper than this are refused: a scene needs a handful
// of levels, and the limit keeps every walk over the tree shallow.
constexpr int kDeepestYamlNesting = 64;
// The most values (scalars, lists and maps) a document may hold: about a
// mesh of 100,000 triangles written out in the scene, and 150 MB of tree.
// Larger meshes belong in model files.
constexpr std::size_t kMostYamlValues = 1'000'000;

// A node of the tree, shared cheaply (an alias is the node of its anchor).
// A default-constructed node is empty (null).
class YamlNode {
 public:
  enum class Kind { Null, Scalar, Sequence, Map };
  struct Data;

  YamlNode() = default;
  explicit YamlNode(std::shared_ptr<const Data> data) : data_(std::move(data)) {}

  Kind kind() const;
  bool isNull() const { return kind() == Kind::Null; }
  bool isScalar() const { return kind() == Kind::Scalar; }
  bool isSequence() const { return kind() == Kind::Sequence; }
  bool isMap() const { return kind() == Kind::Map; }

  // The text of a scalar ("" for other nodes).
  const std::string& scalar() const;
  // A scalar written in quotes (or tagged !!str) is a string even when it
  // looks like a number: "1.5".
  bool isQuoted() const;
  // The value of a plain scalar that YAML reads as a number: decimal, with an
  // optional sign, fraction and exponent, or .inf, -.inf, .nan (an exponent
  // beyond a double's range gives infinity or 0).
  std::optional<double> number() const;
  // The items of a list, or the entries of a map; 0 for other nodes.
  std::size_t size() const;
  const std::vector<YamlNode>& items() const;
  const std::vector<std::pair<YamlNode, YamlNode>>& entries() const;
  Mark mark() const;

 private:
  std::shared_ptr<const Data> data_;
};

struct YamlNode::Data {
  Kind kind = Kind::Null;
  std::string scalar;
  bool quoted = false;
  Mark mark;
  std::vector<YamlNode> items;
  std::vector<std::pair<YamlNode, YamlNode>> entries;
};

// Text that is not YAML ("invalid YAML: ..."), or a document beyond the
// limits above, at the place where the parser found out.
class YamlError : public std::runtime_error {
 public:
  YamlError(Mark mark, const std::string& message) : std::runtime_error(message), mark_(mark) {}
  Mark mark() const { return mark_; }

 private:
  Mark mark_;
};

// The documents of a YAML stream, in order (none for an empty one).
std::vector<YamlNode> parseYamlDocuments(std::string_view text);

}  // namespace rise
