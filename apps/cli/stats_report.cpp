#include "stats_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rise::cli {
namespace {

std::string formatValue(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  return std::to_string(value);
}

}  // namespace

void printStats(std::ostream& out, const RenderDescription& render, const Stats& stats) {
  out << render.algorithm << ": " << render.scene << ", " << render.width << "x" << render.height
      << ", " << render.threads << (render.threads == 1 ? " thread\n" : " threads\n");
  // A column for the names, wide enough for the longest.
  std::size_t width = 28;
  for (const auto& entry : stats.entries()) width = std::max(width, entry.first.size() + 1);
  for (const auto& [name, value] : stats.entries()) {
    std::string label = name;
    label.resize(width, ' ');
    out << "  " << label << formatValue(value) << "\n";
  }
}

void writeStatsJson(const std::filesystem::path& path, const RenderDescription& render,
                    const Stats& stats) {
  nlohmann::ordered_json json = {{"scene", render.scene},
                                 {"algorithm", render.algorithm},
                                 {"width", render.width},
                                 {"height", render.height},
                                 {"threads", render.threads}};
  for (const auto& [name, value] : stats.entries()) json[name] = value;

  writeFileAtomically(path, json.dump(2) + "\n");
}

}  // namespace rise::cli
