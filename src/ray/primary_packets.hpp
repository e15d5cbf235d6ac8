// Whitted's primary rays a packet at a time: where every pixel places its
// samples alike (at its centre, or on a regular grid), a row's samples in
// order lie side by side and their rays are coherent, eight neighbouring
// pixels' centres or the grid of one or two. A row's primary hits are found
// a packet of rays at a time (bvh.hpp) before the row is shaded; each sample
// is then shaded from its hit as tracePrimary would shade it, to the bit.
#pragma once

#include "ray/ray_tracer.hpp"

namespace rise {

// Every pixel of the tile traced as Whitted's ray tracer traces it, its
// samples placed by the render's pattern, which must place them alike in
// every pixel (placesAlikeInEveryPixel).
void traceInPrimaryPackets(const TracingContext& context, TileTrace& tile,
                           const RenderSettings& settings);

}  // namespace rise
