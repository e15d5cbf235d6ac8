#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/color.hpp"
#include "core/sampling.hpp"
#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/material.hpp"
#include "scene/shape.hpp"

namespace rise {

// The longest side of an image, in pixels: its pixels then count within an
// int, and a render's memory is checked against the machine's besides
// (render/render_limits.hpp).
inline constexpr int kLargestImageSide = 32768;

// The image a scene asks for; the command line may override its size.
struct ImageSpec {
  int width = 640;
  int height = 480;
  Color background{0.0f};  // the colour of rays that hit nothing
  PixelSampling sampling;  // anti-aliasing: samples per pixel, their pattern, the filter
};

// Everything that is rendered: what the scene file describes, validated and
// ready for any algorithm.
struct Scene {
  std::string source;  // the scene file's name, for messages
  ImageSpec image;
  Camera camera;
  int animationFrames = 0;  // the frames of its animation; 0: a still image
  Color ambient{0.0f};      // Ia: the ambient light
  std::vector<std::unique_ptr<Light>> lights;
  std::vector<Material> materials;
  std::vector<std::unique_ptr<Shape>> shapes;
  // What loading accepted with a fix, one line each for the person who wrote
  // the scene: "scene.yaml:9:20: warning: ...".
  std::vector<std::string> warnings;
  // Each shape as the scene file names it, "sphere at line 16", for the
  // explanations; empty for a scene built in code.
  std::vector<std::string> shapeNames;
  // The item of the file's `objects` each shape comes from: one item may be
  // several shapes (a model in its own materials). Empty for a scene built
  // in code, whose shapes are its objects.
  std::vector<int> shapeObjects;

  int objectOf(int shape) const {
    return shapeObjects.empty() ? shape : shapeObjects[static_cast<std::size_t>(shape)];
  }

  const Material& materialOf(const Shape& shape) const { return materials[shape.material()]; }
};

}  // namespace rise
