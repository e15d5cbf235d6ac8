// Radiosity's display: the solved light at the elements' corners drawn by a
// visible-surface algorithm (RadiositySettings::display), interpolated
// across each element (Gouraud), with no shadows and no shading of its own:
// the light was solved already.
#pragma once

#include "raster/tessellated_scene.hpp"
#include "render/renderer.hpp"

namespace rise {

// `lit`: the elements' faces, their vertices' light set (vertexRadiance).
RenderResult drawSolution(const Scene& scene, const RenderSettings& settings,
                          RenderObserver& observer, const TessellatedScene& lit);

}  // namespace rise
