#include "reports/colours.hpp"

#include <algorithm>

namespace rise {

const std::vector<std::pair<std::string, std::string>>& shapeColours() {
  static const std::vector<std::pair<std::string, std::string>> colours = {
      {"window", "#ffcc00"}, {"polygon", "#00e5ff"}, {"other", "#ff4081"}, {"behind", "#7c4dff"},
      {"front", "#00e676"},  {"span", "#ffea00"},    {"edge", "#ff9100"},  {"tile", "#ffffff"}};
  return colours;
}

const std::string& colourOfRole(const std::string& role) {
  const auto& colours = shapeColours();
  const auto found = std::find_if(colours.begin(), colours.end(),
                                  [&](const auto& entry) { return entry.first == role; });
  return found != colours.end() ? found->second : colourOfRole("other");
}

const char* colourOfRay(const RayNode& ray) {
  switch (ray.kind) {
    case RayKind::Primary:
      return "#ffffff";
    case RayKind::Shadow:
      return ray.transmittance == Color(0.0f) ? "#ff3d00" : "#ffd600";
    case RayKind::Reflection:
      return "#00e5ff";
    case RayKind::Refraction:
      return "#e040fb";
  }
  return "#ffffff";
}

std::array<std::uint8_t, 3> bytesOfColour(const std::string& hex) {
  const auto byte = [&](std::size_t at) {
    return static_cast<std::uint8_t>(std::stoi(hex.substr(at, 2), nullptr, 16));
  };
  return {byte(1), byte(3), byte(5)};
}

}  // namespace rise
