// Reading a parsed YAML document with a precise message for everything that
// can be wrong with it: each value is read through a Field that knows what
// messages call it ("'radius' in sphere") and where they point, and each map
// through a CheckedMap that rejects missing, repeated and unknown keys.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/color.hpp"
#include "core/math.hpp"
#include "io/yaml_document.hpp"

namespace rise {

// A problem at one place in a document; the scene loader adds the file name.
class YamlValueError : public std::runtime_error {
 public:
  YamlValueError(Mark mark, const std::string& message)
      : std::runtime_error(message), mark_(mark) {}

  Mark mark() const { return mark_; }

 private:
  Mark mark_;
};

// One value of the document, what messages call it, and where they point: at
// the value, or at its key when the value is empty (an empty value has no
// place of its own).
struct Field {
  YamlNode node;
  std::string name;
  Mark mark;
};

Field makeField(const YamlNode& node, std::string name, Mark keyMark);

[[noreturn]] void failAt(Mark mark, const std::string& message);

// "expected <expectation> for <field name>, got <what the value is>".
[[noreturn]] void failExpected(const Field& field, std::string_view expectation);

// A number as people write it: "0.1", "1.7e30".
std::string shortNumber(double value);

// How a value looks to the person who wrote it: "'abc'", "a list of 2 items",
// "nothing"...
std::string describe(const YamlNode& node);

// The candidate closest in spelling to `word`, when it is close enough to be
// a likely typo: "did you mean 'radius'?"; otherwise the list of candidates.
std::string suggestAlternative(std::string_view word, const std::vector<std::string>& candidates);

enum class Bound { Any, NonNegative, Positive };

float readNumber(const Field& field, Bound bound = Bound::Any);
int readWholeNumber(const Field& field, Bound bound = Bound::Any);
Vec3 readVec3(const Field& field);
// A Vec3 that is not zero.
Vec3 readNonZeroVector(const Field& field);
// The unit vector along a Vec3 that is not zero, however long or short it is.
Vec3 readDirection(const Field& field);
Color readColor(const Field& field);  // three numbers >= 0
std::string readName(const Field& field);
float readNonNegative(const Field& field);
float readPositive(const Field& field);
int readPositiveWholeNumber(const Field& field);
// A number from `least` to `most`, both included.
float readNumberFrom(const Field& field, float least, float most);

// One of a fixed set of names, with a suggestion for a misspelt one.
template <typename Choice>
Choice readChoice(const Field& field, const std::vector<std::pair<std::string, Choice>>& choices) {
  const std::string name = readName(field);
  std::vector<std::string> names;
  for (const auto& [choiceName, choice] : choices) {
    if (choiceName == name) return choice;
    names.push_back(choiceName);
  }
  failAt(field.mark, field.name + " is '" + name + "'; " + suggestAlternative(name, names));
}

// The items of a list of minItems to maxItems items, each named `itemName`.
std::vector<Field> readList(const Field& field, std::string_view expectation, std::string itemName,
                            std::size_t minItems = 0,
                            std::size_t maxItems = std::numeric_limits<std::size_t>::max());

// The points [x, y, z] of a list of minPoints to maxPoints, each named
// "a point of <the list's name>".
std::vector<Vec3> readPoints(const Field& field, std::string_view expectation,
                             std::size_t minPoints,
                             std::size_t maxPoints = std::numeric_limits<std::size_t>::max());

// The entries of a map in document order; keys must be plain values and
// appear once in it. Messages call the map `mapName`.
struct MapEntry {
  std::string key;
  Mark keyMark;
  YamlNode value;
};
std::vector<MapEntry> readMap(const Field& field, std::string_view expectation,
                              std::string_view mapName);

// A map with a fixed set of allowed keys, called `name` in messages
// ("sphere", "camera", "material 'red'").
class CheckedMap {
 public:
  CheckedMap(const Field& field, std::string name, std::vector<std::string> allowedKeys);

  // The value of a key that must be there: "sphere is missing 'radius'".
  Field required(std::string_view key) const;
  std::optional<Field> optional(std::string_view key) const;
  // Where the map is, for a problem with it as a whole.
  Mark mark() const { return mark_; }

 private:
  std::string name_;
  Mark mark_;
  std::vector<MapEntry> entries_;
};

// Reads `key` into `value` when the map has it, keeping the default otherwise.
template <typename T, typename Read>
void readIfPresent(const CheckedMap& map, std::string_view key, T& value, Read read) {
  if (const std::optional<Field> field = map.optional(key)) value = read(*field);
}

// An item of a list that names its kind by its one key, with its properties
// under it: "- sphere: {center: [0, 0, 0], radius: 1}". `kindWord` is what
// messages call the kinds ("shape", "light type").
MapEntry readKindAndProperties(const Field& item, std::string_view kindWord,
                               const std::vector<std::string>& kinds);

}  // namespace rise
