// The shapes a step draws over the image (Warnock's window, the scanline's
// spans and active edges, a pair depth sort compared), in the colours of their
// roles, burnt into a copy of the frame: pictures for a book or a slide, where
// the step player draws the same shapes over the image in the browser.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "render/step_recorder.hpp"

namespace rise {

// Each role a step's shape may have, with its colour as "#rrggbb" (sRGB).
const std::vector<std::pair<std::string, std::string>>& shapeColours();

// Draws the outlines of `shapes`, one pixel wide, over `image`.
void drawShapes(Image& image, const std::vector<StepShape>& shapes);

}  // namespace rise
