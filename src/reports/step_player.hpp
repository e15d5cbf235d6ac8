// The step player: a folder that shows an algorithm at work, step by step, in
// any browser, with no server and no network.
//
//   index.html        the player: the image as it stood after each step with
//                     the step's shapes and pixels drawn over it, the step in
//                     words, its numbers and tables, the counts so far;
//                     previous, next, play, pause, speed and a slider
//   steps.json        the steps (reports/step_json.hpp gives the schema)
//   frames/NNNN.png   the image after each step shown; depth/NNNN.png the
//                     depth buffer, for the algorithms that keep one
//   image.png, <buffer>.png   the render's image and auxiliary buffers
#pragma once

#include <filesystem>

#include "render/renderer.hpp"

namespace rise {

struct StepPlayerInput {
  const Scene& scene;
  const AlgorithmDescription& algorithm;
  const RenderResult& result;
  const StepRecorder& recorder;
};

// Writes the player into `directory`, made if missing. Throws ImageFileError
// or std::runtime_error when a file cannot be written.
void writeStepPlayer(const std::filesystem::path& directory, const StepPlayerInput& input);

}  // namespace rise
