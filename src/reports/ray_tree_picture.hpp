// A pixel's ray trees as a picture a class can look at: on the left the scene
// seen from the camera with the rays drawn over it, on the right the scene
// seen from beside the rays, where their bounces show. An SVG file, with the
// two renders beside it as PNG files.
#pragma once

#include <filesystem>
#include <vector>

#include "render/renderer.hpp"

namespace rise {

// Writes `svg` and, beside it, <name>.camera.png (the render `image`) and
// <name>.side.png (the scene rendered by the z-buffer from beside the rays,
// for which the scene's camera is moved and then put back). Throws
// ImageFileError or std::runtime_error when a file cannot be written.
void writeRayTreePicture(const std::filesystem::path& svg, Scene& scene,
                         const RenderSettings& settings, const Image& image,
                         const std::vector<RayTree>& trees);

}  // namespace rise
