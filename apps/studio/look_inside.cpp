// Looking inside an algorithm: the step player, which replays the steps a
// render recorded (the image as it stood after each, the step's shapes drawn
// over it, its sentence, numbers and tables), and the tree of rays behind a
// pixel of a ray-traced image, as a tree of numbers and as lines in the
// viewport.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "algorithms/registry.hpp"
#include "core/text.hpp"
#include "io/atomic_file.hpp"
#include "reports/colours.hpp"
#include "reports/ray_tree_text.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

ImU32 roleColour(const std::string& role) {
  const auto bytes = bytesOfColour(colourOfRole(role));
  return IM_COL32(bytes[0], bytes[1], bytes[2], 255);
}

Vec3 rayColour(const RayNode& ray) {
  const auto bytes = bytesOfColour(colourOfRay(ray));
  return Vec3(bytes[0], bytes[1], bytes[2]) / 255.0f;
}

// How far a ray that hit nothing is drawn.
constexpr float kMissLength = 20.0f;

std::vector<SceneLine> linesOf(const RayTree& tree) {
  std::vector<SceneLine> lines;
  for (const RayNode& ray : tree.rays) {
    const float length = ray.hit && std::isfinite(ray.distance) ? ray.distance : kMissLength;
    lines.push_back({ray.origin, ray.origin + ray.direction * length, rayColour(ray)});
  }
  return lines;
}

}  // namespace

void Studio::startPlayer(const RenderJob& job) {
  player_.replay.reset();
  player_.algorithm = std::string(job.renderer().name());
  player_.steps = job.recorder()->keptSteps();
  player_.notDetailed = job.recorder()->stepsNotDetailed();
  player_.finalImage = job.result().image;
  player_.background = job.scene()->image.background;
  player_.playing = false;
  player_.bringForward = true;
  showStep(-1);
}

void Studio::showStep(int step) {
  const int last = static_cast<int>(player_.steps.size()) - 1;
  step = std::clamp(step, -1, last);
  // Forward from where it is; backward from the start.
  if (step < player_.current || !player_.replay) {
    player_.replay = std::make_unique<StepReplay>(player_.background, player_.finalImage);
    player_.current = -1;
  }
  for (int i = player_.current + 1; i <= step; ++i)
    player_.replay->apply(player_.steps[static_cast<std::size_t>(i)]);
  player_.current = step;
  player_.texture.upload(player_.showDepth && player_.replay->hasDepths()
                             ? player_.replay->depthImage()
                             : player_.replay->image());
}

void Studio::inspectPixel(const glm::ivec2& pixel) {
  const std::optional<RenderSettings> settings = settingsToRender();
  if (!settings || !render_.result) return;
  StepBudget budget;
  budget.treePixel = pixel;
  // Only the pixel's own tile is worth telling.
  budget.region = PixelRect{pixel.x, pixel.y, pixel.x + 1, pixel.y + 1};
  inspection_.job = std::make_unique<RenderJob>(*findRenderer(render_.algorithm), session_.scene(),
                                                *settings, budget);
  inspection_.pixel = pixel;
  inspection_.algorithm = render_.algorithm;
  inspection_.scene = session_.scene();
  inspection_.pixelColor = render_.result->image.at(pixel.x, pixel.y);
  inspection_.trees.clear();
  note("tracing the rays of pixel " + std::to_string(pixel.x) + ", " + std::to_string(pixel.y));
}

void Studio::finishInspection() {
  if (inspection_.job->succeeded()) {
    inspection_.trees = inspection_.job->recorder()->trees();
    inspection_.sample = 0;
    inspection_.bringForward = true;
    viewport_.showLines(inspection_.trees.empty() ? std::vector<SceneLine>()
                                                  : linesOf(inspection_.trees.front()));
    const std::string pixel =
        std::to_string(inspection_.pixel.x) + ", " + std::to_string(inspection_.pixel.y);
    note(inspection_.trees.empty()
             ? "pixel " + pixel +
                   ": no ray tree recorded (the adaptive pattern traces no fixed samples: "
                   "choose another pattern)"
             : "pixel " + pixel + ": " + counted(inspection_.trees.size(), "sample") +
                   " traced; their rays are in the Ray tree panel and the viewport");
  }
  inspection_.job.reset();
}

void Studio::drawStepOverlay(const Step& step, const ImageViewShown& shown) {
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  for (const StepShape& shape : step.shapes) {
    const ImU32 colour = roleColour(shape.role);
    std::vector<ImVec2> points;
    for (const Vec2& point : shape.points) points.push_back(shown.onScreen(point));
    if (points.empty()) continue;
    switch (shape.kind) {
      case StepShape::Kind::Rectangle:
        if (points.size() >= 2) draw.AddRect(points[0], points[1], colour, 0.0f, 0, 2.0f);
        break;
      case StepShape::Kind::Polygon:
        draw.AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_Closed,
                         2.0f);
        break;
      case StepShape::Kind::Segment:
        draw.AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 2.0f);
        break;
      case StepShape::Kind::Point:
        draw.AddCircleFilled(points[0], 3.0f, colour);
        break;
    }
  }
}

void Studio::drawSteps() {
  const int count = static_cast<int>(player_.steps.size());
  ImGui::Text("%s: %d steps kept", player_.algorithm.c_str(), count);
  if (ImGui::Button("|<")) showStep(-1);
  ImGui::SameLine();
  if (ImGui::Button("<")) showStep(player_.current - 1);
  track("step back");
  ImGui::SameLine();
  if (ImGui::Button(player_.playing ? "Pause" : "Play")) player_.playing = !player_.playing;
  track("Play");
  ImGui::SameLine();
  if (ImGui::Button(">")) showStep(player_.current + 1);
  track("step forward");
  ImGui::SameLine();
  if (ImGui::Button(">|")) showStep(count - 1);
  track("last step");
  ImGui::SameLine();
  if (player_.replay && player_.replay->hasDepths()) {
    if (ImGui::Checkbox("depth", &player_.showDepth)) showStep(player_.current);
    ImGui::SameLine();
  }
  ImGui::SetNextItemWidth(140);
  ImGui::SliderFloat("steps/s", &player_.stepsPerSecond, 1.0f, 200.0f, "%.0f",
                     ImGuiSliderFlags_Logarithmic);
  int position = player_.current + 1;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderInt("##step", &position, 0, count, "step %d")) showStep(position - 1);
  if (player_.playing) {
    player_.due += ImGui::GetIO().DeltaTime * player_.stepsPerSecond;
    const int advance = static_cast<int>(player_.due);
    player_.due -= advance;
    if (advance > 0) showStep(player_.current + advance);
    if (player_.current == count - 1) player_.playing = false;
  }
  const Step* step =
      player_.current >= 0 ? &player_.steps[static_cast<std::size_t>(player_.current)] : nullptr;
  ImGui::TextWrapped("%s", step ? step->text.c_str() : "Before the first step.");
  if (step && step->skippedBefore > 0)
    ImGui::TextDisabled("(%d steps before it not kept)", step->skippedBefore);
  const float side = ImGui::GetContentRegionAvail().x * 0.4f;
  ImGui::BeginChild("step details", {side, 0}, true, ImGuiWindowFlags_HorizontalScrollbar);
  if (step) {
    for (const auto& [name, value] : step->values) ImGui::Text("%s: %g", name.c_str(), value);
    for (const StepTable& table : step->tables) {
      ImGui::TextUnformatted(table.title.c_str());
      if (table.columns.empty() ||
          // Columns as wide as their cells, scrolled sideways where the
          // panel is narrower, never cut.
          !ImGui::BeginTable(
              table.title.c_str(), static_cast<int>(table.columns.size()),
              ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                  ImGuiTableFlags_ScrollY,
              {0.0f, ImGui::GetTextLineHeightWithSpacing() *
                         static_cast<float>(std::min<std::size_t>(table.rows.size(), 12) + 3)}))
        continue;
      for (const std::string& column : table.columns) ImGui::TableSetupColumn(column.c_str());
      ImGui::TableHeadersRow();
      for (const std::vector<StepCell>& row : table.rows) {
        ImGui::TableNextRow();
        for (const StepCell& cell : row) {
          ImGui::TableNextColumn();
          if (const double* number = std::get_if<double>(&cell))
            ImGui::Text("%g", *number);
          else
            ImGui::TextUnformatted(std::get<std::string>(cell).c_str());
        }
      }
      ImGui::EndTable();
    }
  }
  ImGui::EndChild();
  ImGui::SameLine();
  const ImageViewShown shown =
      drawImageView("step image", player_.texture, player_.view, ImGui::GetContentRegionAvail());
  track("step image");
  if (step) drawStepOverlay(*step, shown);
}

void Studio::drawRayNode(const RayTree& tree, int ray) {
  const RayNode& node = tree.rays[static_cast<std::size_t>(ray)];
  std::ostringstream text;
  printRay(text, *inspection_.scene, node, "");
  const std::string lines = text.str();
  const std::size_t firstEnd = lines.find('\n');
  const std::string label = lines.substr(0, firstEnd) + "##ray" + std::to_string(ray);
  if (!ImGui::TreeNodeEx(label.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::TextDisabled("%s", lines.substr(firstEnd + 1).c_str());
  for (int child : node.children) drawRayNode(tree, child);
  ImGui::TreePop();
}

bool Studio::saveRayTree(const std::filesystem::path& path) {
  std::ostringstream text;
  printRayTrees(text, *inspection_.scene, inspection_.trees, inspection_.pixelColor);
  try {
    writeFileAtomically(path, text.str());
  } catch (const std::exception& error) {
    note(error.what());
    return false;
  }
  return wrote(path);
}

void Studio::drawRayTreePanel() {
  if (inspection_.trees.empty()) return;
  placeAtFirst({960, 580}, {640, 400});
  ImGui::Begin("Ray tree");
  trackPanel("ray tree");
  const int samples = static_cast<int>(inspection_.trees.size());
  ImGui::Text("%s, pixel %d, %d", inspection_.algorithm.c_str(), inspection_.pixel.x,
              inspection_.pixel.y);
  if (inspection_.scene != session_.scene()) {
    ImGui::TextColored({1.0f, 0.6f, 0.2f, 1.0f},
                       "Out of date: the scene has changed since this pixel was traced; render "
                       "and click it again.");
    track("ray tree/out of date");
  }
  if (samples > 1) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    if (ImGui::SliderInt("sample", &inspection_.sample, 0, samples - 1))
      viewport_.showLines(linesOf(inspection_.trees[static_cast<std::size_t>(inspection_.sample)]));
  }
  const RayTree& tree = inspection_.trees[static_cast<std::size_t>(inspection_.sample)];
  ImGui::Text("sample %d at %.4g, %.4g: colour %.4g %.4g %.4g; %zu rays", tree.sample,
              tree.raster.x, tree.raster.y, tree.color.r, tree.color.g, tree.color.b,
              tree.rays.size());
  ImGui::TextDisabled(
      "In the viewport: primary white, shadow yellow, reflection blue, refraction green.");
  ImGui::BeginChild("rays");
  if (!tree.rays.empty()) drawRayNode(tree, 0);
  ImGui::EndChild();
  track("ray tree");
  ImGui::End();
}

}  // namespace rise::studio
