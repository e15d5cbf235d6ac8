#include "io/yaml_document.hpp"

#include <yaml.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <system_error>

namespace rise {

YamlNode::Kind YamlNode::kind() const { return data_ ? data_->kind : Kind::Null; }

const std::string& YamlNode::scalar() const {
  static const std::string kNone;
  return data_ ? data_->scalar : kNone;
}

bool YamlNode::isQuoted() const { return data_ && data_->quoted; }

namespace {

bool isOneOf(std::string_view text, std::initializer_list<std::string_view> words) {
  return std::find(words.begin(), words.end(), text) != words.end();
}

std::size_t digitsAt(std::string_view text, std::size_t position) {
  std::size_t end = position;
  while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
  return end - position;
}

// Whether the text is a decimal number: [+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?
bool isDecimal(std::string_view text) {
  std::size_t at = text.starts_with('+') || text.starts_with('-') ? 1 : 0;
  const std::size_t whole = digitsAt(text, at);
  at += whole;
  std::size_t fraction = 0;
  if (at < text.size() && text[at] == '.') {
    fraction = digitsAt(text, ++at);
    at += fraction;
  }
  if (whole == 0 && fraction == 0) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    const std::size_t exponent = digitsAt(text, at);
    if (exponent == 0) return false;
    at += exponent;
  }
  return at == text.size();
}

}  // namespace

std::optional<double> YamlNode::number() const {
  if (!isScalar() || isQuoted()) return std::nullopt;
  const std::string_view text = scalar();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (isOneOf(text, {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"})) return kInfinity;
  if (isOneOf(text, {"-.inf", "-.Inf", "-.INF"})) return -kInfinity;
  if (isOneOf(text, {".nan", ".NaN", ".NAN"})) return std::numeric_limits<double>::quiet_NaN();
  if (!isDecimal(text)) return std::nullopt;
  const bool negative = text.starts_with('-');
  const std::string_view digits = text.substr(text.starts_with('+') ? 1 : 0);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) {
    const bool tiny =
        text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos;
    return (negative ? -1.0 : 1.0) * (tiny ? 0.0 : kInfinity);
  }
  return value;
}

std::size_t YamlNode::size() const {
  if (!data_) return 0;
  return data_->kind == Kind::Map ? data_->entries.size() : data_->items.size();
}

const std::vector<YamlNode>& YamlNode::items() const {
  static const std::vector<YamlNode> kNone;
  return data_ ? data_->items : kNone;
}

const std::vector<std::pair<YamlNode, YamlNode>>& YamlNode::entries() const {
  static const std::vector<std::pair<YamlNode, YamlNode>> kNone;
  return data_ ? data_->entries : kNone;
}

Mark YamlNode::mark() const { return data_ ? data_->mark : Mark{}; }

namespace {

Mark characterMarkOf(const yaml_mark_t& mark) {
  return Mark{static_cast<int>(mark.line), static_cast<int>(mark.column)};
}

YamlError invalidYaml(Mark mark, const std::string& problem) {
  return YamlError(mark, "invalid YAML: " + problem);
}

std::string quotedCharacter(char c) { return std::string("'") + c + "'"; }

Mark shownMark(std::string_view text, Mark characters) {
  return ShownMarks(text).shown(characters);
}

Mark shownMarkAt(std::string_view text, std::size_t offset) {
  return shownMark(text, characterMarkAt(text, offset));
}

// A tab where libyaml wants indentation: YAML indents with spaces only. Said
// at the line's ':' when it has one, where a reader of the line looks.
YamlError tabError(std::string_view text, std::size_t tab, Mark where) {
  std::size_t lineStart = tab;
  while (lineStart > 0 && lineBreakAt(text, lineStart - 1) == 0) --lineStart;
  const bool inIndentation =
      text.substr(lineStart, tab - lineStart).find_first_not_of(" \t") == std::string_view::npos;
  for (std::size_t i = tab; inIndentation && i < text.size() && lineBreakAt(text, i) == 0; ++i) {
    if (text[i] == ':' && (i + 1 == text.size() || text[i + 1] == ' ' || lineBreakAt(text, i + 1)))
      return invalidYaml(
          shownMarkAt(text, i),
          "unexpected ':' (wrong indentation, a tab, or a value with ': ' that needs quotes?)");
  }
  return invalidYaml(where, "a tab in the indentation; YAML indents with spaces");
}

std::string unclosedBracket(std::optional<char> found, char opening, char closing) {
  const char otherClosing = closing == ']' ? '}' : ']';
  if (found == otherClosing)
    return "unexpected " + quotedCharacter(otherClosing) +
           "; check that the brackets before it are closed in order";
  return std::string(closing == ']' ? "a list" : "a map") + " opened with " +
         quotedCharacter(opening) + " is not closed with " + quotedCharacter(closing);
}

// libyaml's complaint, said as what is wrong with the scene text.
YamlError syntaxError(const yaml_parser_t& parser, std::string_view text) {
  if (parser.error == YAML_READER_ERROR)
    return invalidYaml(shownMarkAt(text, parser.problem_offset),
                       std::string("the text is not readable: ") + parser.problem);
  const Mark problemCharacter = characterMarkOf(parser.problem_mark);
  const Mark where = shownMark(text, problemCharacter);
  const Mark context = shownMark(text, characterMarkOf(parser.context_mark));
  const std::optional<std::size_t> offset = offsetOfCharacter(text, problemCharacter);
  const std::optional<char> found =
      offset ? std::optional<char>(text[*offset]) : std::optional<char>();
  const std::string problem = parser.problem ? parser.problem : "unknown problem";
  const std::string contextText = parser.context ? parser.context : "";
  if (problem == "did not find expected ',' or ']'")
    return invalidYaml(where, unclosedBracket(found, '[', ']'));
  if (problem == "did not find expected ',' or '}'")
    return invalidYaml(where, unclosedBracket(found, '{', '}'));
  if (problem == "mapping values are not allowed in this context")
    return invalidYaml(
        where,
        "unexpected ':' (wrong indentation, a tab, or a value with ': ' that needs quotes?)");
  if (found == '\t') return tabError(text, *offset, where);
  if (problem == "did not find expected node content" || problem ==
                                                             "found character that "
                                                             "cannot start any token")
    return invalidYaml(where, found ? "unexpected " + quotedCharacter(*found) +
                                          "; expected a value (quote text that starts "
                                          "with it)"
                                    : "the text ends where a value was expected");
  if (problem == "did not find expected key")
    return invalidYaml(where, "expected a key of the map begun on line " +
                                  std::to_string(context.line + 1) +
                                  " at its indentation (wrong indentation?)");
  if (problem == "could not find expected ':'")
    return invalidYaml(context,
                       "expected 'key: value' on this line; a value on a line of its own "
                       "is indented under its key");
  if (contextText == "while scanning a quoted scalar")
    return invalidYaml(context, "a quoted text is not closed");
  return invalidYaml(where, contextText.empty() ? problem : problem + " (" + contextText + ")");
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {
    yaml_parser_initialize(&parser_);
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()),
                                 text.size());
  }
  ~Parser() { yaml_parser_delete(&parser_); }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;

  // The next event into `event`, which the caller deletes.
  void next(yaml_event_t& event) {
    if (!yaml_parser_parse(&parser_, &event)) throw syntaxError(parser_, text_);
  }

 private:
  yaml_parser_t parser_;
  std::string_view text_;
};

class Event {
 public:
  explicit Event(Parser& parser) { parser.next(event_); }
  ~Event() { yaml_event_delete(&event_); }
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;
  const yaml_event_t& get() const { return event_; }

 private:
  yaml_event_t event_;
};

std::string textOf(const yaml_char_t* text) {
  return text ? reinterpret_cast<const char*>(text) : "";
}

bool isNullWord(std::string_view text) {
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

std::shared_ptr<YamlNode::Data> scalarData(const yaml_event_t& event, Mark mark) {
  auto data = std::make_shared<YamlNode::Data>();
  const auto& scalar = event.data.scalar;
  data->mark = mark;
  data->scalar.assign(reinterpret_cast<const char*>(scalar.value), scalar.length);
  const std::string tag = textOf(scalar.tag);
  data->quoted = scalar.style != YAML_PLAIN_SCALAR_STYLE || tag == "!" || tag == YAML_STR_TAG;
  const bool plainNull = !data->quoted && tag.empty() && isNullWord(data->scalar);
  data->kind = plainNull || tag == YAML_NULL_TAG ? YamlNode::Kind::Null : YamlNode::Kind::Scalar;
  return data;
}

// Builds the documents' trees from the events, keeping open lists and maps
// on a stack.
class TreeBuilder {
 public:
  explicit TreeBuilder(std::string_view text) : marks_(text) {}

  void openCollection(YamlNode::Kind kind, const yaml_event_t& event, const yaml_char_t* anchor) {
    countValue(event);
    if (open_.size() >= static_cast<std::size_t>(kDeepestYamlNesting))
      throw YamlError(markOf(event), "lists and maps nested more than " +
                                         std::to_string(kDeepestYamlNesting) +
                                         " deep; a scene needs only a few levels");
    auto data = std::make_shared<YamlNode::Data>();
    data->kind = kind;
    data->mark = markOf(event);
    open_.push_back(OpenCollection{data, textOf(anchor), std::nullopt, values_});
  }

  void closeCollection() {
    OpenCollection closed = std::move(open_.back());
    open_.pop_back();
    add(YamlNode(closed.data), closed.anchor, values_ - closed.valuesBefore + 1);
  }

  void addScalar(const yaml_event_t& event) {
    countValue(event);
    add(YamlNode(scalarData(event, markOf(event))), textOf(event.data.scalar.anchor), 1);
  }

  // An alias is its anchor's node again, shared, not copied; but whoever
  // reads the tree reads it again, so its values count again: a few lines
  // of aliases of aliases would otherwise stand for billions of values.
  void addAlias(const yaml_event_t& event) {
    const std::string name = textOf(event.data.alias.anchor);
    const auto anchored = anchors_.find(name);
    if (anchored == anchors_.end())
      throw invalidYaml(markOf(event), "unknown alias '*" + name +
                                           "'; expected the name of an anchor '&" + name +
                                           "' given to a value before it");
    const Anchored repeated = anchored->second;
    values_ += repeated.values;
    if (values_ > kMostYamlValues)
      throw YamlError(markOf(event),
                      "the alias '*" + name + "' repeats " + std::to_string(repeated.values) +
                          " values, making more than " + std::to_string(kMostYamlValues) +
                          " in the scene; expected fewer repetitions, or a large mesh in a "
                          "model file (mesh: {file})");
    add(repeated.node, "", repeated.values);
  }

  std::vector<YamlNode> documents() && { return std::move(documents_); }

 private:
  struct OpenCollection {
    std::shared_ptr<YamlNode::Data> data;
    std::string anchor;
    std::optional<YamlNode> pendingKey;
    std::size_t valuesBefore;  // the values counted before this one
  };

  // A node an anchor names, and the values it stands for, its own and
  // those it holds, counted again through every alias.
  struct Anchored {
    YamlNode node;
    std::size_t values;
  };

  Mark markOf(const yaml_event_t& event) { return marks_.shown(characterMarkOf(event.start_mark)); }

  void countValue(const yaml_event_t& event) {
    if (++values_ > kMostYamlValues)
      throw YamlError(markOf(event),
                      "more than " + std::to_string(kMostYamlValues) +
                          " values in the scene; expected a larger mesh in a model file "
                          "(mesh: {file})");
  }

  void add(YamlNode node, const std::string& anchor, std::size_t values) {
    if (!anchor.empty()) anchors_[anchor] = Anchored{node, values};
    if (open_.empty()) {
      documents_.push_back(std::move(node));
      anchors_.clear();
      return;
    }
    OpenCollection& parent = open_.back();
    if (parent.data->kind == YamlNode::Kind::Sequence) {
      parent.data->items.push_back(std::move(node));
    } else if (!parent.pendingKey) {
      parent.pendingKey = std::move(node);
    } else {
      parent.data->entries.emplace_back(std::move(*parent.pendingKey), std::move(node));
      parent.pendingKey.reset();
    }
  }

  ShownMarks marks_;
  std::vector<OpenCollection> open_;
  std::map<std::string, Anchored> anchors_;
  std::vector<YamlNode> documents_;
  std::size_t values_ = 0;
};

}  // namespace

std::vector<YamlNode> parseYamlDocuments(std::string_view text) {
  Parser parser(text);
  TreeBuilder builder(text);
  for (;;) {
    const Event next(parser);
    const yaml_event_t& event = next.get();
    switch (event.type) {
      case YAML_STREAM_END_EVENT:
        return std::move(builder).documents();
      case YAML_SCALAR_EVENT:
        builder.addScalar(event);
        break;
      case YAML_ALIAS_EVENT:
        builder.addAlias(event);
        break;
      case YAML_SEQUENCE_START_EVENT:
        builder.openCollection(YamlNode::Kind::Sequence, event, event.data.sequence_start.anchor);
        break;
      case YAML_MAPPING_START_EVENT:
        builder.openCollection(YamlNode::Kind::Map, event, event.data.mapping_start.anchor);
        break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT:
        builder.closeCollection();
        break;
      default:
        break;  // stream and document starts, document ends: nothing to build
    }
  }
}

}  // namespace rise
