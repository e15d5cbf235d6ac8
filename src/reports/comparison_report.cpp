#include "reports/comparison_report.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/byte_encoding.hpp"
#include "reports/counter_glossary.hpp"

namespace rise {
namespace {

constexpr const char* kReports[] = {"results.csv", "results.md", "index.html"};

const double* findValue(const Stats& stats, const std::string& name) {
  for (const auto& [key, value] : stats.entries())
    if (key == name) return &value;
  return nullptr;
}

std::string formatNumber(double value) {
  std::ostringstream out;
  if (std::isfinite(value) && std::abs(value) < 1e18 && value == std::trunc(value))
    out << static_cast<long long>(value);
  else
    out << std::setprecision(4) << value;
  return out.str();
}

std::string escapeHtml(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::string csv(const std::vector<ComparedRender>& renders, const std::vector<std::string>& names) {
  std::ostringstream out;
  out << "algorithm";
  for (const std::string& name : names) out << "," << name;
  out << "\n";
  for (const ComparedRender& render : renders) {
    out << std::string(render.algorithm->name);
    for (const std::string& name : names) out << "," << statisticCell(render.result.stats, name);
    out << "\n";
  }
  return out.str();
}

std::string markdown(const std::string& sceneName, const std::vector<ComparedRender>& renders,
                     const std::vector<std::string>& names) {
  std::ostringstream out;
  out << "# " << sceneName << "\n\n| |";
  for (const ComparedRender& render : renders)
    out << " " << std::string(render.algorithm->name) << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < renders.size(); ++i) out << "---:|";
  out << "\n";
  for (const std::string& name : names) {
    out << "| " << name << " |";
    for (const ComparedRender& render : renders)
      out << " " << statisticCell(render.result.stats, name) << " |";
    out << "\n";
  }
  return out.str();
}

// A horizontal bar a render, as long as its time: no script, no library.
std::string timeChart(const std::vector<ComparedRender>& renders) {
  double longest = 0.0;
  for (const ComparedRender& render : renders)
    longest = std::max(longest, render.result.stats.value("render_seconds"));
  constexpr int kBarHeight = 22, kLabelWidth = 220, kBarWidth = 480;
  std::ostringstream out;
  out << "<svg width=\"" << kLabelWidth + kBarWidth + 90 << "\" height=\""
      << kBarHeight * renders.size() + 4 << "\" role=\"img\" aria-label=\"render times\">\n";
  for (std::size_t i = 0; i < renders.size(); ++i) {
    const double seconds = renders[i].result.stats.value("render_seconds");
    const double width = longest > 0.0 ? kBarWidth * seconds / longest : 0.0;
    const std::size_t y = i * kBarHeight;
    out << "<text x=\"0\" y=\"" << y + 15 << "\">"
        << escapeHtml(std::string(renders[i].algorithm->name)) << "</text><rect x=\"" << kLabelWidth
        << "\" y=\"" << y + 3 << "\" width=\"" << width << "\" height=\"" << kBarHeight - 6
        << "\" fill=\"#4a7fb5\"/><text x=\"" << kLabelWidth + width + 6 << "\" y=\"" << y + 15
        << "\">" << formatNumber(seconds) << " s</text>\n";
  }
  out << "</svg>\n";
  return out.str();
}

// "ray-tracing" -> "ray_tracing", as counters are named.
std::string counterWord(std::string_view name) {
  std::string word(name);
  std::replace(word.begin(), word.end(), '-', '_');
  return word;
}

// The shadows an image has, as its caption says.
std::string shadowsOf(const ComparedRender& render) {
  const Stats& stats = render.result.stats;
  constexpr const char* kNoLight = "no shadows: no light casts them";
  if (render.algorithm->family != Family::VisibleSurface)
    return stats.value("shadow_rays") > 0.0 ? "shadows by shadow rays" : kNoLight;
  if (stats.value("shadow_map_texels") > 0.0) return "shadows by shadow maps";
  if (stats.value("shadow_volume_faces") > 0.0) return "shadows by shadow volumes";
  if (findValue(stats, "shadow_map_texels") || findValue(stats, "shadow_volume_faces"))
    return kNoLight;
  return "no shadows (--shadows map or volume draws them)";
}

// The smallest part of a render's time its caption tells in seconds.
constexpr double kSmallestShare = 0.005;

// Where a visible-surface render's time went: its shadows, its visible
// surfaces, its shading and the rest (tessellating and projecting the scene).
std::string timeSplitOf(const ComparedRender& render) {
  const Stats& stats = render.result.stats;
  if (render.algorithm->family != Family::VisibleSurface) return "";
  const double total = stats.value("render_seconds");
  double rest = total;
  std::string split;
  const auto part = [&](const char* counter, const char* what) {
    if (!findValue(stats, counter)) return;
    const double seconds = stats.value(counter);
    rest -= seconds;
    // Shading is estimated from a sample of pixels; what is left beside it
    // when it takes nearly all is too little to tell from zero.
    split +=
        (seconds < kSmallestShare * total ? "under 0.5% of it" : formatNumber(seconds) + " s") +
        " " + what + ", ";
  };
  // A scene without lights has shadow maps or volumes of none.
  if (stats.value("shadow_map_texels") > 0.0) part("shadow_map_seconds", "drawing the shadow maps");
  if (stats.value("shadow_volume_faces") > 0.0)
    part("shadow_volume_seconds", "building the shadow volumes");
  part("visible_surface_seconds", "finding the visible surfaces");
  part("shading_seconds", "shading");
  return "Of its " + formatNumber(total) + " s: " + split + formatNumber(std::max(rest, 0.0)) +
         " s preparing (tessellation, projection, buffers).";
}

// Why a render slower than the algorithm it draws the image of is so, from
// their counters, or nothing where it is faster.
std::string whySlower(const ComparedRender& render, const std::vector<ComparedRender>& renders) {
  const std::string other(render.algorithm->sameImageAs);
  const auto reference = std::find_if(renders.begin(), renders.end(), [&](const auto& candidate) {
    return !other.empty() && candidate.algorithm->name == other;
  });
  const Stats& ours = render.result.stats;
  const double* speedup = findValue(ours, "speedup_over_" + counterWord(other));
  if (reference == renders.end() || !speedup || *speedup >= 1.0) return "";
  const Stats& theirs = reference->result.stats;
  const double spared = ours.value("primary_rays_from_item_buffer");
  const double theirRays = theirs.value("rays");
  const double sparedSeconds =
      theirRays > 0.0 ? theirs.value("render_seconds") * spared / theirRays : 0.0;
  return "Slower than " + other + " here (" + formatNumber(*speedup) +
         " times its speed): its item buffer took " +
         formatNumber(ours.value("item_buffer_seconds")) + " s, and the " + formatNumber(spared) +
         " primary rays it spared would have taken " + other + " about " +
         formatNumber(sparedSeconds) + " s, as its acceleration structure finds a first hit in " +
         formatNumber(theirs.value("intersection_tests_per_ray")) +
         " tests a ray on this scene. The item buffer pays where first hits are dear: many "
         "objects, no acceleration (--accel none), large images.";
}

std::string html(const std::string& sceneName, const std::vector<ComparedRender>& renders,
                 const std::vector<std::string>& names) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>RISE: "
      << escapeHtml(sceneName)
      << "</title>\n<style>body{font-family:sans-serif;margin:2em}"
         ".images{display:flex;flex-wrap:wrap;gap:1em}figure{margin:0}"
         "figcaption{font-size:90%;max-width:320px}img{max-width:320px;image-rendering:pixelated}"
         "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;"
         "padding:2px 8px}td{text-align:right}td.meaning{text-align:left;font-size:90%}"
         ".slower{color:#8a4b00}</style></head><body>\n<h1>"
      << escapeHtml(sceneName) << "</h1>\n<div class=\"images\">\n";
  for (const ComparedRender& render : renders) {
    out << "<figure><a href=\"" << escapeHtml(std::string(render.algorithm->name))
        << ".png\"><img src=\"" << escapeHtml(std::string(render.algorithm->name))
        << ".png\" alt=\"" << escapeHtml(std::string(render.algorithm->name))
        << "\"></a><figcaption><b>" << escapeHtml(std::string(render.algorithm->name))
        << "</b>: " << escapeHtml(std::string(render.algorithm->summary)) << "<br><i>"
        << escapeHtml(shadowsOf(render)) << "</i>";
    if (const std::string split = timeSplitOf(render); !split.empty())
      out << "<br>" << escapeHtml(split);
    if (const std::string why = whySlower(render, renders); !why.empty())
      out << "<br><span class=\"slower\">" << escapeHtml(why) << "</span>";
    out << "</figcaption></figure>\n";
  }
  out << "</div>\n<h2>Render time</h2>\n"
      << timeChart(renders) << "<h2>Counters</h2>\n<table><tr><th></th><th>what it counts</th>";
  for (const ComparedRender& render : renders)
    out << "<th>" << escapeHtml(std::string(render.algorithm->name)) << "</th>";
  out << "</tr>\n";
  for (const std::string& name : names) {
    const std::string meaning(counterMeaning(name).value_or(""));
    out << "<tr><th title=\"" << escapeHtml(meaning) << "\">" << escapeHtml(name)
        << "</th><td class=\"meaning\">" << escapeHtml(meaning) << "</td>";
    for (const ComparedRender& render : renders)
      out << "<td>" << statisticCell(render.result.stats, name) << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n</body></html>\n";
  return out.str();
}

int pixelsDiffering(const Image& a, const Image& b, Encoding encoding) {
  const ByteEncoder& toByte = byteEncoder(encoding);
  int differing = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      bool differs = false;
      for (int channel = 0; channel < 3; ++channel)
        differs |= std::abs(toByte(a.at(x, y)[channel]) - toByte(b.at(x, y)[channel])) > 2;
      differing += differs ? 1 : 0;
    }
  }
  return differing;
}

}  // namespace

// Every statistic any algorithm reported, in the order they first appear.
std::vector<std::string> statisticNames(const std::vector<ComparedRender>& renders) {
  std::vector<std::string> names;
  for (const ComparedRender& render : renders)
    for (const auto& [name, value] : render.result.stats.entries())
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::string statisticCell(const Stats& stats, const std::string& name) {
  const double* value = findValue(stats, name);
  return value != nullptr ? formatNumber(*value) : "";
}

void addSameImageCounters(std::vector<ComparedRender>& renders, Encoding encoding) {
  for (ComparedRender& render : renders) {
    const std::string_view other = render.algorithm->sameImageAs;
    const auto reference = std::find_if(renders.begin(), renders.end(), [&](const auto& candidate) {
      return !other.empty() && candidate.algorithm->name == other;
    });
    if (reference == renders.end()) continue;
    const Stats& theirs = reference->result.stats;
    Stats& ours = render.result.stats;
    ours.add("pixels_differing_from_" + counterWord(other),
             pixelsDiffering(render.result.image, reference->result.image, encoding));
    ours.add("intersection_tests_saved",
             theirs.value("intersection_tests") - ours.value("intersection_tests"));
    // A render not timed (as a tile's piece may be) has no speed to compare.
    if (const double seconds = ours.value("render_seconds"); seconds > 0.0)
      ours.add("speedup_over_" + counterWord(other), theirs.value("render_seconds") / seconds);
  }
}

std::vector<std::filesystem::path> comparisonFiles(
    const std::filesystem::path& directory, const std::vector<std::string_view>& algorithms) {
  std::vector<std::filesystem::path> files;
  for (std::string_view algorithm : algorithms)
    files.push_back(directory / (std::string(algorithm) + ".png"));
  for (const char* report : kReports) files.push_back(directory / report);
  return files;
}

std::vector<std::filesystem::path> writeComparison(const std::filesystem::path& directory,
                                                   const std::string& sceneName,
                                                   const std::vector<ComparedRender>& renders,
                                                   Encoding encoding) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw std::runtime_error(directory.string() + ": cannot create (" + error.message() + ")");

  std::vector<std::string_view> algorithms;
  for (const ComparedRender& render : renders) algorithms.push_back(render.algorithm->name);
  const std::vector<std::filesystem::path> files = comparisonFiles(directory, algorithms);
  for (std::size_t i = 0; i < renders.size(); ++i)
    writeImage(renders[i].result.image, files[i], encoding);
  const std::vector<std::string> names = statisticNames(renders);
  // Titled by the scene's file, not by where it lies.
  const std::string title = std::filesystem::path(sceneName).filename().string();
  const std::string reports[] = {csv(renders, names), markdown(title, renders, names),
                                 html(title, renders, names)};
  for (std::size_t i = 0; i < std::size(reports); ++i)
    writeFileAtomically(files[renders.size() + i], reports[i]);
  return files;
}

}  // namespace rise
