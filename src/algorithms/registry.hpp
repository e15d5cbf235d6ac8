#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "render/renderer.hpp"

namespace rise {

// Every algorithm RISE offers, in the order the manual presents them. Adding
// an algorithm means adding its file and one line to this table.
std::span<const Renderer* const> allRenderers();

// The algorithm with this name, or nullptr.
const Renderer* findRenderer(std::string_view name);

// What a front end does with an algorithm when the user names none.
enum class Use {
  Render,   // rise render, rise-mpi, the studio's render
  Explain,  // rise explain: steps worth watching one by one
  Inspect,  // rise inspect: a ray tree worth reading
};
const Renderer& defaultRenderer(Use use);

// The algorithms a comparison side by side starts with (the studio's
// compare panel): a ray tracer and a visible-surface algorithm. `rise
// compare` with no algorithm named compares every one.
std::vector<const Renderer*> defaultComparison();

// The algorithms that offer a look (Look::RayTrees: those `rise inspect`
// accepts), in the table's order.
std::vector<const Renderer*> renderersOffering(Look look);

// Renders and adds the wall-clock time, "render_seconds", to the statistics,
// measured the same way for every algorithm (and, for algorithms that count
// their "rays", the throughput "rays_per_second").
RenderResult renderTimed(const Renderer& renderer, const Scene& scene,
                         const RenderSettings& settings, RenderObserver& observer);

}  // namespace rise
