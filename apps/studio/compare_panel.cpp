// The compare panel: the scene rendered by several algorithms, one after the
// other, shown side by side zooming and panning together; the table of their
// times and counters (the same rows as `rise compare`'s page, which it can
// write); and the difference between any two.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "core/text.hpp"
#include "reports/counter_glossary.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

// |a - b| per pixel and channel, and the largest of them.
std::pair<Image, double> differenceOf(const Image& a, const Image& b) {
  Image difference(a.width(), a.height());
  double largest = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Color d = glm::abs(a.at(x, y) - b.at(x, y));
      difference.at(x, y) = d;
      largest = std::max(largest, static_cast<double>(std::max({d.r, d.g, d.b})));
    }
  return {difference, largest};
}

}  // namespace

void Studio::startComparison(const std::vector<std::string>& algorithms) {
  if (algorithms.empty()) {
    note("choose the algorithms to compare");
    return;
  }
  std::optional<RenderSettings> settings = settingsToRender();
  if (!settings) return;
  if (comparison_.comparedShadows) settings->shadows = kComparedShadows;
  comparison_.scene = session_.scene();
  comparison_.job.reset();
  comparison_.renders.clear();
  comparison_.textures.clear();
  comparison_.differenceOf[0] = comparison_.differenceOf[1] = -1;
  comparison_.pending.assign(algorithms.rbegin(), algorithms.rend());
  const Renderer& first = *findRenderer(comparison_.pending.back());
  comparison_.pending.pop_back();
  comparison_.job = std::make_unique<RenderJob>(first, session_.scene(), *settings);
}

void Studio::finishComparisonStep() {
  RenderJob& job = *comparison_.job;
  if (!job.succeeded()) {
    note(std::string(job.renderer().name()) + ": " +
         (job.failure().empty() ? "cancelled" : job.failure()));
    comparison_.pending.clear();
    comparison_.job.reset();
    return;
  }
  comparison_.renders.push_back({&job.renderer().description(), job.result()});
  comparison_.textures.emplace_back().upload(job.result().image);
  if (comparison_.pending.empty()) {
    note("compared " + counted(comparison_.renders.size(), "algorithm"));
    comparison_.job.reset();
    return;
  }
  const Renderer& next = *findRenderer(comparison_.pending.back());
  comparison_.pending.pop_back();
  comparison_.job = std::make_unique<RenderJob>(next, job.scene(), job.settings());
}

bool Studio::writeComparisonPage(const std::filesystem::path& directory) {
  if (comparison_.renders.empty()) {
    note("nothing is compared yet");
    return false;
  }
  try {
    writeComparison(directory, session_.scene() ? session_.scene()->source : "scene",
                    comparison_.renders, Encoding::Srgb);
  } catch (const std::exception& error) {
    note(error.what());
    return false;
  }
  return wrote(directory / "index.html");
}

void Studio::drawComparePanel() {
  placeAtFirst({400, 460}, {560, 520});
  ImGui::Begin("Compare");
  trackPanel("compare");
  const std::span<const Renderer* const> renderers = allRenderers();
  const float rightEdge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  const ImGuiStyle& style = ImGui::GetStyle();
  for (std::size_t i = 0; i < renderers.size(); ++i) {
    const std::string name(renderers[i]->name());
    bool chosen = std::ranges::find(comparison_.chosen, name) != comparison_.chosen.end();
    if (ImGui::Checkbox(name.c_str(), &chosen)) {
      std::erase(comparison_.chosen, name);
      if (chosen) comparison_.chosen.push_back(name);
    }
    track("compare/" + name);
    // The next box on this line where it fits whole, else on the next line.
    if (i + 1 == renderers.size()) break;
    const float nextWidth = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
                            ImGui::CalcTextSize(std::string(renderers[i + 1]->name()).c_str()).x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + nextWidth <= rightEdge) ImGui::SameLine();
  }
  ImGui::Checkbox("Shadow maps, as rise compare draws them", &comparison_.comparedShadows);
  track("compare/shadows");
  ImGui::BeginDisabled(!session_.scene() || comparison_.job != nullptr);
  if (ImGui::Button("Compare")) {
    std::vector<std::string> inOrder;  // the registry's order, as `rise compare` renders them
    for (const Renderer* renderer : allRenderers())
      if (std::ranges::find(comparison_.chosen, renderer->name()) != comparison_.chosen.end())
        inOrder.emplace_back(renderer->name());
    startComparison(inOrder);
  }
  track("Compare");
  ImGui::EndDisabled();
  if (comparison_.job) {
    ImGui::SameLine();
    if (ImGui::Button("Cancel##compare")) comparison_.job->cancel();
    ImGui::SameLine();
    ImGui::Text("%s: %.0f%%", std::string(comparison_.job->renderer().name()).c_str(),
                comparison_.job->fractionDone() * 100.0);
  }
  if (!comparison_.renders.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Write page..."))
      browser_.show(FileBrowser::Purpose::Folder, "Write the comparison into a folder",
                    outputFolder() / "comparison",
                    [this](const auto& path) { writeComparisonPage(path); });
    if (comparison_.scene != session_.scene() && !comparison_.job) {
      ImGui::TextColored({1.0f, 0.6f, 0.2f, 1.0f},
                         "Out of date: the scene has changed since; Compare again.");
      track("compare/out of date");
    }
    const int count = static_cast<int>(comparison_.renders.size());
    const float width = (ImGui::GetContentRegionAvail().x - 8.0f * (count - 1)) / count;
    const float height = std::max(120.0f, ImGui::GetContentRegionAvail().y * 0.5f);
    for (int i = 0; i < count; ++i) {
      if (i > 0) ImGui::SameLine(0, 8);
      ImGui::BeginGroup();
      const ComparedRender& render = comparison_.renders[static_cast<std::size_t>(i)];
      ImGui::Text("%s  %.3f s", std::string(render.algorithm->name).c_str(),
                  render.result.stats.value("render_seconds"));
      drawImageView(("compared " + std::to_string(i)).c_str(),
                    comparison_.textures[static_cast<std::size_t>(i)], comparison_.view,
                    {width, height - ImGui::GetTextLineHeightWithSpacing()});
      track("compared/" + std::string(render.algorithm->name));
      ImGui::EndGroup();
    }
    if (ImGui::BeginTabBar("compare tabs")) {
      if (ImGui::BeginTabItem("Times and counters")) {
        drawCompareTable();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Difference")) {
        drawDifference();
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
}

void Studio::drawCompareTable() {
  const std::vector<std::string> names = statisticNames(comparison_.renders);
  const int columns = static_cast<int>(comparison_.renders.size()) + 1;
  if (!ImGui::BeginTable("counters", columns,
                         ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg))
    return;
  ImGui::TableSetupScrollFreeze(1, 1);
  ImGui::TableSetupColumn("");
  for (const ComparedRender& render : comparison_.renders)
    ImGui::TableSetupColumn(std::string(render.algorithm->name).c_str());
  ImGui::TableHeadersRow();
  for (const std::string& name : names) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name.c_str());
    if (const std::optional<std::string_view> meaning = counterMeaning(name);
        meaning && ImGui::IsItemHovered())
      ImGui::SetTooltip("%.*s", static_cast<int>(meaning->size()), meaning->data());
    for (const ComparedRender& render : comparison_.renders) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(statisticCell(render.result.stats, name).c_str());
    }
  }
  ImGui::EndTable();
}

void Studio::drawDifference() {
  const int count = static_cast<int>(comparison_.renders.size());
  const auto pick = [&](const char* label, int& index) {
    index = std::clamp(index, 0, count - 1);
    ImGui::SetNextItemWidth(180);
    if (ImGui::BeginCombo(
            label, std::string(comparison_.renders[static_cast<std::size_t>(index)].algorithm->name)
                       .c_str())) {
      for (int i = 0; i < count; ++i)
        if (ImGui::Selectable(
                std::string(comparison_.renders[static_cast<std::size_t>(i)].algorithm->name)
                    .c_str(),
                i == index))
          index = i;
      ImGui::EndCombo();
    }
  };
  pick("and", comparison_.first);
  ImGui::SameLine();
  pick("##second", comparison_.second);
  if (comparison_.differenceOf[0] != comparison_.first ||
      comparison_.differenceOf[1] != comparison_.second) {
    const Image& a = comparison_.renders[static_cast<std::size_t>(comparison_.first)].result.image;
    const Image& b = comparison_.renders[static_cast<std::size_t>(comparison_.second)].result.image;
    auto [difference, largest] = differenceOf(a, b);
    comparison_.largestDifference = largest;
    comparison_.difference.upload(difference);
    comparison_.differenceOf[0] = comparison_.first;
    comparison_.differenceOf[1] = comparison_.second;
  }
  ImGui::Text("|a - b| per pixel (linear, shown as sRGB); the largest: %.4g",
              comparison_.largestDifference);
  drawImageView("difference", comparison_.difference, comparison_.view,
                ImGui::GetContentRegionAvail());
}

}  // namespace rise::studio
