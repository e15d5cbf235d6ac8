// The auxiliary buffers of a render (RenderResult::buffers) made visible: raw
// depths, normals and intersection counts become images a person can read.
// The images hold display values in [0, 1], already spaced for the eye: write
// them with Encoding::Linear so that they are stored unchanged.
#pragma once

#include <string_view>

#include "core/image.hpp"

namespace rise {

// The display image of the raw buffer called `name`:
//  "depth"  grey: the nearest hit white, the farthest hit black, linear in
//           the inverse depth 1/d between (as a z-buffer keeps it), so that
//           the far reaches of a floor do not crush the near surfaces into a
//           few levels; pixels that hit nothing (infinite depth) black.
//  "normal" each unit normal n as the colour 0.5 n + 0.5 (x red, y green,
//           z blue); pixels that hit nothing (zero normal) black.
//  "cost"   each pixel's count of intersection tests divided by the largest
//           count, through the Turbo colour map: dark blue for the cheapest,
//           then cyan, green, yellow and red to dark red for the dearest.
//           Turbo: A. Mikhailov, "Turbo, An Improved Rainbow Colormap for
//           Visualization", Google AI Blog, 2019, in R. Du's polynomial fit.
//  "face"   each face number as a colour of its own, picked by hashing the
//           number, so that neighbouring faces differ; no face (-1) black.
//  "shadow-map" grey by the inverse of the depth seen from the light: the
//           nearest white, half as bright twice as far, nothing black (an
//           infinite plane's far reaches would crush a linear scale).
//  "variance" each pixel's standard error (the square root of its mean's
//           variance) over the largest, on the cost's Turbo colours: where
//           a progressive render is still noisy.
// Throws std::invalid_argument for any other name.
Image visualizeBuffer(std::string_view name, const Image& raw);

}  // namespace rise
