#pragma once

#include <span>
#include <string_view>

#include "render/renderer.hpp"

namespace rise {

// Every algorithm RISE offers, in the order the manual presents them. Adding
// an algorithm means adding its file and one line to this table.
std::span<const Renderer* const> allRenderers();

// The algorithm with this name, or nullptr.
const Renderer* findRenderer(std::string_view name);

// Renders and adds the wall-clock time, "render_seconds", to the statistics,
// measured the same way for every algorithm (and, for algorithms that count
// their "rays", the throughput "rays_per_second").
RenderResult renderTimed(const Renderer& renderer, const Scene& scene,
                         const RenderSettings& settings, RenderObserver& observer);

}  // namespace rise
