// The colours a reader learns once and meets everywhere RISE draws over an
// image: in the step player, in frames with shapes, in a ray tree's picture
// and in the studio.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/ray_tree.hpp"

namespace rise {

// Each role a step's shape may have, with its colour as "#rrggbb" (sRGB);
// "other" is the colour of any role not listed.
const std::vector<std::pair<std::string, std::string>>& shapeColours();
const std::string& colourOfRole(const std::string& role);

// A ray's colour by its kind; a blocked shadow ray has a colour of its own.
const char* colourOfRay(const RayNode& ray);

// "#rrggbb" as its three bytes.
std::array<std::uint8_t, 3> bytesOfColour(const std::string& hex);

}  // namespace rise
