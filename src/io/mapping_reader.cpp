#include "io/mapping_reader.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/text.hpp"

namespace rise {

namespace {

// Each name, with its projection (none for the shape's own coordinates).
const std::vector<std::pair<std::string, std::optional<Projection>>> kMappings{
    {"uv", std::nullopt},
    {"spherical", Projection::Spherical},
    {"cylindrical", Projection::Cylindrical},
    {"planar", Projection::Planar},
    {"box", Projection::Box}};

// The mappings that turn around an axis, and so take one.
const std::vector<std::string> kTurning{"spherical", "cylindrical"};

std::vector<std::string> mappingNames() {
  std::vector<std::string> names;
  for (const auto& [name, projection] : kMappings) names.push_back(name);
  return names;
}

std::optional<Projection> projectionNamed(const std::string& name) {
  return std::find_if(kMappings.begin(), kMappings.end(),
                      [&](const auto& entry) { return entry.first == name; })
      ->second;
}

// "mapping: {cylindrical: {axis: [0, 0, 1]}}".
Mapping readTurningMapping(const Field& field) {
  const std::string expectation =
      "a mapping (" + joined(mappingNames()) +
      "), or a map {spherical: {axis: [x, y, z]}} or {cylindrical: {axis: [x, y, z]}}";
  if (field.node.size() != 1) failExpected(field, expectation);
  const MapEntry entry = readMap(field, expectation, field.name).front();
  const std::vector<std::string> names = mappingNames();
  if (std::find(names.begin(), names.end(), entry.key) == names.end())
    failAt(entry.keyMark, "unknown mapping " + inQuotes(entry.key) + " in " + field.name + "; " +
                              suggestAlternative(entry.key, names));
  if (std::find(kTurning.begin(), kTurning.end(), entry.key) == kTurning.end())
    failAt(entry.keyMark, "the " + entry.key + " mapping takes no axis; expected 'mapping: " +
                              entry.key + "', or an axis for spherical or cylindrical");
  const std::string name = "the " + entry.key + " mapping";
  const CheckedMap properties(makeField(entry.value, name, entry.keyMark), name, {"axis"});
  return {*projectionNamed(entry.key), readDirection(properties.required("axis"))};
}

}  // namespace

std::optional<Mapping> readMapping(const Field& field) {
  if (field.node.isMap()) return readTurningMapping(field);
  const std::optional<Projection> projection = readChoice(field, kMappings);
  if (!projection) return std::nullopt;
  return Mapping{*projection};
}

}  // namespace rise
