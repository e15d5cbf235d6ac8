// Whitted's adaptive supersampling (Whitted 1980), which every ray tracer
// offers as the adaptive pattern: a pixel's corners are traced first, and
// where their colours differ by more than a threshold the square is
// quartered and its new corners traced, down to as many levels as the
// samples allow (16 samples, two levels of quarters). A pixel's colour is the
// average of its squares'. The corners are shared by the pixels around them,
// and so traced once each.
#pragma once

#include "ray/ray_tracer.hpp"

namespace rise {

// Every pixel of the tile sampled adaptively, each sample traced by `trace`
// with values drawn at random but for where it lies.
void sampleAdaptively(TileTrace& tile, const RenderSettings& settings, const TraceSample& trace);

}  // namespace rise
