// Steps and ray trees as JSON, for tools and for the step player's page. The
// schema, version 1:
//
//   steps file   {"rise": "steps", "version": 1, "scene", "algorithm",
//                 "width", "height", "every", "region": [x, y, w, h] | null,
//                 "steps_recorded", "steps_not_detailed", "stats": {name: value},
//                 "buffers": [file], "steps": [step]}
//   step         {"index", "kind", "text", "skipped_before",
//                 "values": {name: number},
//                 "tables": [{"title", "columns": [name], "rows": [[number | word]]}],
//                 "shapes": [{"kind": "rectangle" | "polygon" | "segment" | "point",
//                             "role", "points": [[x, y]]}],
//                 "painted": [[y, x0, x1]], "hidden": [[y, x0, x1]],
//                 "settled": [[x, y, w, h]],
//                 "so_far": {"kinds": {kind: count}, "painted", "hidden", "settled"},
//                 "frame": file, "depth_frame": file (when the step drew depths)}
//   ray trees    {"rise": "ray-tree", "version": 1, "scene", "algorithm",
//                 "pixel": [x, y], "color": [r, g, b], "samples": [tree]}
//   tree         {"sample", "raster": [x, y], "color": [r, g, b],
//                 "lens": [u, v], "time", "light": [u, v], "gloss": [u, v]
//                 (distributed ray tracing), "rays": [ray]}
//   ray          {"index", "kind", "depth", "parent", "children": [index],
//                 "origin", "direction", "weight", "contribution", "color",
//                 "hit", "object", "object_name", "distance", "point",
//                 "normal", "uv", "ambient" (on a hit), "light",
//                 "transmittance", "diffuse", "specular" (shadow rays)}
//
// Raster coordinates run from (0, 0) at the image's top-left corner; pixel
// (i, j) covers [i, i+1) x [j, j+1). "painted" and "hidden" are the runs of
// pixels the step set and those where it lost a depth test, "settled" the
// rectangles whose pixels it made final; "so_far" counts what this step and
// every step before it did, those not kept in the file included. Colours are
// linear.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/renderer.hpp"

namespace rise {

// What a steps file says of the render around its steps.
struct StepsHeader {
  std::string scene;
  std::string algorithm;
  int width;
  int height;
  int every;
  std::optional<PixelRect> region;
  std::size_t stepsRecorded;
  std::uint64_t stepsNotDetailed;
  const Stats* stats;
  std::vector<std::string> buffers;
};

// A step's JSON, with its frames' file names (empty: none).
std::string stepJson(const Step& step, int index, const std::string& frame,
                     const std::string& depthFrame);
// The steps file around steps already in JSON.
std::string stepsJson(const StepsHeader& header, const std::vector<std::string>& steps);

// The ray trees of one pixel; `color` is the pixel's.
std::string rayTreesJson(const Scene& scene, std::string_view algorithm,
                         const std::vector<RayTree>& trees, const Color& color);

// A shape as a student finds it: "object 2, sphere at line 16".
std::string objectName(const Scene& scene, int object);

}  // namespace rise
