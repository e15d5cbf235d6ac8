// What each counter an algorithm reports counts, in one line: the
// comparison page shows it beside the counter, and the manual's chapters tell
// more. A counter an algorithm adds must be given its line here, which the
// tests hold every algorithm to.
#pragma once

#include <optional>
#include <string_view>

namespace rise {

// The line for counter `name`, or nothing for a counter without one. The
// counters named after another algorithm ("speedup_over_ray_tracing") are
// told for any algorithm.
std::optional<std::string_view> counterMeaning(std::string_view name);

}  // namespace rise
