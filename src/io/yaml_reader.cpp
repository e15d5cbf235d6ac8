#include "io/yaml_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unordered_set>
#include <utility>

#include "core/text.hpp"

namespace rise {

namespace {

constexpr std::size_t kLongestValueShown = 40;
constexpr std::size_t kMostKeysListed = 6;

std::string describeScalar(const YamlNode& node) {
  if (node.isQuoted()) return "the string " + inQuotes(node.scalar(), '"');
  const std::string& text = node.scalar();
  return node.number() && text.size() <= kLongestValueShown ? text : inQuotes(text);
}

std::string describeSequence(const YamlNode& node) {
  if (node.size() == 0) return "an empty list";
  std::vector<std::string> items;
  for (const YamlNode& item : node.items()) {
    if (!item.isScalar()) break;
    items.push_back(describeScalar(item));
  }
  const std::string bracketed = std::string("[").append(joined(items)).append("]");
  if (items.size() == node.size() && bracketed.size() <= kLongestValueShown) return bracketed;
  return node.size() == 1 ? "a list of 1 item"
                          : "a list of " + std::to_string(node.size()) + " items";
}

std::string describeMap(const YamlNode& node) {
  if (node.size() == 0) return "an empty map";
  if (node.size() > kMostKeysListed) return "a map of " + std::to_string(node.size()) + " keys";
  std::vector<std::string> keys;
  for (const auto& entry : node.entries())
    keys.push_back(entry.first.isScalar() ? entry.first.scalar() : "?");
  return (keys.size() == 1 ? "a map with the key " : "a map with the keys ") + joined(keys);
}

// The optimal string alignment distance: the Levenshtein edit distance with
// the swap of two neighbouring letters counted as one edit, the commonest
// typing slip.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

std::string numberExpectation(Bound bound, std::string_view kind) {
  switch (bound) {
    case Bound::NonNegative:
      return std::string(kind) + " >= 0";
    case Bound::Positive:
      return std::string(kind) + " > 0";
    case Bound::Any:
      break;
  }
  return std::string(kind);
}

bool withinBound(double value, Bound bound) {
  switch (bound) {
    case Bound::NonNegative:
      return value >= 0.0;
    case Bound::Positive:
      return value > 0.0;
    case Bound::Any:
      break;
  }
  return true;
}

double readBoundedNumber(const Field& field, Bound bound, std::string_view kind) {
  const std::optional<double> value = field.node.number();
  if (!value) failExpected(field, numberExpectation(bound, kind));
  if (!std::isfinite(*value) || std::abs(*value) > std::numeric_limits<float>::max())
    failExpected(field, numberExpectation(bound, "a finite number"));
  if (!withinBound(*value, bound)) failExpected(field, numberExpectation(bound, kind));
  return *value;
}

}  // namespace

std::string shortNumber(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.3g", value);
  std::string written = text.data();
  // "1e+30" and "1e-05" as "1e30" and "1e-5".
  if (const std::size_t e = written.find('e'); e != std::string::npos) {
    std::string exponent = written.substr(e + 1);
    const bool negative = exponent.starts_with('-');
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    written = written.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return written;
}

Field makeField(const YamlNode& node, std::string name, Mark keyMark) {
  return Field{node, std::move(name), node.isNull() ? keyMark : node.mark()};
}

void failAt(Mark mark, const std::string& message) { throw YamlValueError(mark, message); }

void failExpected(const Field& field, std::string_view expectation) {
  failAt(field.mark,
         field.name + " is " + describe(field.node) + "; expected " + std::string(expectation));
}

std::string describe(const YamlNode& node) {
  switch (node.kind()) {
    case YamlNode::Kind::Scalar:
      return describeScalar(node);
    case YamlNode::Kind::Sequence:
      return describeSequence(node);
    case YamlNode::Kind::Map:
      return describeMap(node);
    case YamlNode::Kind::Null:
      break;
  }
  return "empty";
}

std::string suggestAlternative(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string lowerWord = lowercase(word);
  const std::string* best = nullptr;
  std::size_t bestDistance = std::numeric_limits<std::size_t>::max();
  for (const std::string& candidate : candidates) {
    // The distance is at least the difference in length: a word too much
    // longer or shorter is not measured (a name of millions of letters is
    // no typo, and measuring it would take their square in memory).
    const std::size_t longer = std::max(word.size(), candidate.size());
    const std::size_t shorter = std::min(word.size(), candidate.size());
    if (2 * (longer - shorter) > longer) continue;
    const std::size_t distance = editDistance(lowerWord, lowercase(candidate));
    if (distance < bestDistance) {
      best = &candidate;
      bestDistance = distance;
    }
  }
  // Close enough when at most half the letters of the longer word differ:
  // "radus" is "radius", but "n" is not "ks".
  if (best && 2 * bestDistance <= std::max(word.size(), best->size()))
    return "did you mean " + inQuotes(*best) + "?";
  return "expected one of: " + joined(candidates);
}

float readNumber(const Field& field, Bound bound) {
  return static_cast<float>(readBoundedNumber(field, bound, "a number"));
}

int readWholeNumber(const Field& field, Bound bound) {
  const std::string expectation = numberExpectation(bound, "a whole number");
  const double value = readBoundedNumber(field, bound, "a whole number");
  if (value != std::floor(value)) failExpected(field, expectation);
  if (value > std::numeric_limits<int>::max())
    failExpected(
        field, expectation + " that is at most " + std::to_string(std::numeric_limits<int>::max()));
  if (value < std::numeric_limits<int>::min())
    failExpected(field, expectation + " that is at least " +
                            std::to_string(std::numeric_limits<int>::min()));
  return static_cast<int>(value);
}

float readNumberFrom(const Field& field, float least, float most) {
  const float value = readNumber(field);
  if (value < least || value > most)
    failExpected(field, "a number from " + shortNumber(least) + " to " + shortNumber(most));
  return value;
}

Vec3 readVec3(const Field& field) {
  const std::vector<Field> coordinates =
      readList(field, "a list of 3 numbers [x, y, z]", "a coordinate of " + field.name, 3, 3);
  return Vec3(readNumber(coordinates[0]), readNumber(coordinates[1]), readNumber(coordinates[2]));
}

Vec3 readNonZeroVector(const Field& field) {
  const Vec3 vector = readVec3(field);
  if (vector == Vec3(0.0f)) failExpected(field, "a vector that is not zero");
  return vector;
}

Vec3 readDirection(const Field& field) {
  const Vec3 vector = readVec3(field);
  if (vector == Vec3(0.0f)) failExpected(field, "a direction, not the zero vector");
  return normalizedOrZero(vector);
}

Color readColor(const Field& field) {
  const std::vector<Field> components =
      readList(field, "a colour [r, g, b] of 3 numbers >= 0", "a component of " + field.name, 3, 3);
  return Color(readNumber(components[0], Bound::NonNegative),
               readNumber(components[1], Bound::NonNegative),
               readNumber(components[2], Bound::NonNegative));
}

std::string readName(const Field& field) {
  if (!field.node.isScalar()) failExpected(field, "a name");
  return field.node.scalar();
}

float readNonNegative(const Field& field) { return readNumber(field, Bound::NonNegative); }
float readPositive(const Field& field) { return readNumber(field, Bound::Positive); }
int readPositiveWholeNumber(const Field& field) { return readWholeNumber(field, Bound::Positive); }

std::vector<Field> readList(const Field& field, std::string_view expectation, std::string itemName,
                            std::size_t minItems, std::size_t maxItems) {
  if (!field.node.isSequence() || field.node.size() < minItems || field.node.size() > maxItems)
    failExpected(field, expectation);
  std::vector<Field> items;
  for (const YamlNode& item : field.node.items())
    items.push_back(makeField(item, itemName, field.mark));
  return items;
}

std::vector<Vec3> readPoints(const Field& field, std::string_view expectation,
                             std::size_t minPoints, std::size_t maxPoints) {
  std::vector<Vec3> points;
  for (const Field& point :
       readList(field, expectation, "a point of " + field.name, minPoints, maxPoints))
    points.push_back(readVec3(point));
  return points;
}

std::vector<MapEntry> readMap(const Field& field, std::string_view expectation,
                              std::string_view mapName) {
  if (!field.node.isMap()) failExpected(field, expectation);
  std::vector<MapEntry> entries;
  // Reserved, so that the keys seen stay where they are as entries are added.
  entries.reserve(field.node.size());
  std::unordered_set<std::string_view> keys;
  for (const auto& keyAndValue : field.node.entries()) {
    const YamlNode& key = keyAndValue.first;
    if (!key.isScalar())
      failAt(key.mark(),
             "a key in " + std::string(mapName) + " is " + describe(key) + "; expected a name");
    if (keys.contains(key.scalar()))
      failAt(key.mark(), "duplicate key " + inQuotes(key.scalar()) + " in " + std::string(mapName) +
                             "; a key may appear only once");
    entries.push_back(MapEntry{key.scalar(), key.mark(), keyAndValue.second});
    keys.insert(entries.back().key);
  }
  return entries;
}

CheckedMap::CheckedMap(const Field& field, std::string name, std::vector<std::string> allowedKeys)
    : name_(std::move(name)),
      mark_(field.mark),
      entries_(readMap(field, "a map with the keys " + joined(allowedKeys), name_)) {
  for (const MapEntry& entry : entries_) {
    if (std::find(allowedKeys.begin(), allowedKeys.end(), entry.key) == allowedKeys.end())
      failAt(entry.keyMark, "unknown key " + inQuotes(entry.key) + " in " + name_ + "; " +
                                suggestAlternative(entry.key, allowedKeys));
  }
}

Field CheckedMap::required(std::string_view key) const {
  std::optional<Field> field = optional(key);
  if (!field) failAt(mark_, name_ + " is missing " + inQuotes(key));
  return *std::move(field);
}

std::optional<Field> CheckedMap::optional(std::string_view key) const {
  for (const MapEntry& entry : entries_) {
    if (entry.key == key)
      return makeField(entry.value, inQuotes(key) + " in " + name_, entry.keyMark);
  }
  return std::nullopt;
}

MapEntry readKindAndProperties(const Field& item, std::string_view kindWord,
                               const std::vector<std::string>& kinds) {
  const std::string expectation = "a map with one key naming the " + std::string(kindWord) + " (" +
                                  joined(kinds) + ") and its properties indented under it";
  if (!item.node.isMap() || item.node.size() != 1) failExpected(item, expectation);
  const MapEntry entry = readMap(item, expectation, item.name).front();
  if (std::find(kinds.begin(), kinds.end(), entry.key) == kinds.end())
    failAt(entry.keyMark, "unknown " + std::string(kindWord) + " " + inQuotes(entry.key) + "; " +
                              suggestAlternative(entry.key, kinds));
  return entry;
}

}  // namespace rise
