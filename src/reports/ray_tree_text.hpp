// A pixel's ray trees as an indented text, for the terminal: each ray under
// the one that spawned it, with its kind, where it went, what it hit, the
// Phong terms and shadow verdicts there, its weight and what it added to the
// pixel.
#pragma once

#include <ostream>
#include <vector>

#include "render/ray_tree.hpp"
#include "scene/scene.hpp"

namespace rise {

void printRayTrees(std::ostream& out, const Scene& scene, const std::vector<RayTree>& trees,
                   const Color& pixelColor);

}  // namespace rise
